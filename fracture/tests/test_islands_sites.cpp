// Islands (one piece per connected chunk), the site sources and anisotropic cells.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>

#include "fracture/fracture.hpp"
#include "fracture/islands.hpp"
#include "fracture/tests/meshes.hpp"

using namespace dtlab;
using test::small_torus;

namespace {

// An axis-aligned box [lo, hi], outward (or inward with `inward`).
void add_box(TriangleMesh& m, const Point3& lo, const Point3& hi, bool inward = false) {
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  for (int k = 0; k < 8; ++k)
    m.vertices.push_back({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
  const std::uint32_t q[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (auto& f : q) {
    std::array<std::uint32_t, 3> a{base + f[0], base + f[1], base + f[2]}, b{base + f[0], base + f[2], base + f[3]};
    if (inward) std::swap(a[1], a[2]), std::swap(b[1], b[2]);
    m.triangles.push_back(a);
    m.triangles.push_back(b);
  }
}

PieceMesh as_piece(TriangleMesh m) {
  PieceMesh p;
  p.cut.assign(m.triangles.size(), 0);
  p.cut_tag.assign(m.triangles.size(), -1);
  p.mesh = std::move(m);
  return p;
}

// Edge-connected components of a triangle mesh.
std::size_t components(const TriangleMesh& m) {
  PieceMesh p = as_piece(m);
  return split_islands(p).size();
}

double volume_sum(const FractureResult& r) {
  return std::accumulate(r.pieces.begin(), r.pieces.end(), 0.0, [](double s, const Piece& p) { return s + p.volume; });
}

void check_islands(const FractureResult& r) {
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const Piece& p = r.pieces[i];
    CHECK(p.volume > 0);
    CHECK(p.island < static_cast<std::int64_t>(p.site_islands));
    for (auto j : p.neighbors) {
      CHECK(j != i);
      const auto& nj = r.pieces[j].neighbors;
      CHECK(std::find(nj.begin(), nj.end(), static_cast<std::uint32_t>(i)) != nj.end());
    }
  }
  CHECK(std::abs(volume_sum(r) - r.mesh_volume) <= 1e-12 * r.mesh_volume);
}
}  // namespace

TEST_CASE("split_islands: two boxes are two islands, a cavity stays with its shell") {
  TriangleMesh two;
  add_box(two, {0, 0, 0}, {1, 1, 1});
  add_box(two, {2, 0, 0}, {4, 1, 1});
  const auto parts = split_islands(as_piece(two));
  REQUIRE(parts.size() == 2);
  CHECK(signed_volume(parts[0].mesh) == Approx(2.0));  // largest first
  CHECK(signed_volume(parts[1].mesh) == Approx(1.0));
  CHECK(parts[0].mesh.vertices.size() == 8);

  TriangleMesh hollow;  // a box with a cavity, and a small box inside the cavity
  add_box(hollow, {0, 0, 0}, {3, 3, 3});
  add_box(hollow, {1, 1, 1}, {2, 2, 2}, true);
  add_box(hollow, {1.4, 1.4, 1.4}, {1.6, 1.6, 1.6});
  const auto h = split_islands(as_piece(hollow));
  REQUIRE(h.size() == 2);
  CHECK(signed_volume(h[0].mesh) == Approx(26.0));  // shell minus cavity
  CHECK(h[0].mesh.triangles.size() == 24);
  CHECK(signed_volume(h[1].mesh) == Approx(0.008));  // the box floating in the cavity
}

TEST_CASE("fracture: one piece per island, adjacency between islands, --no-island-split keeps them") {
  const TriangleMesh torus = make_bumpy_torus();  // the CLI's builtin: 6 sites, seed 1 give an island
  FractureOptions o;
  o.pieces = 6;
  o.seed = 1;
  o.threads = 2;
  const FractureResult split = fracture_mesh(torus, o);
  o.island_split = false;
  const FractureResult whole = fracture_mesh(torus, o);
  check_islands(split);
  check_islands(whole);
  std::size_t multi_split = 0, multi_whole = 0;
  for (const auto& p : split.pieces) multi_split += components(p.geometry.mesh) > 1;
  for (const auto& p : whole.pieces) multi_whole += components(p.geometry.mesh) > 1;
  CHECK(multi_split == 0);
  CHECK(multi_whole > 0);  // this torus and these sites do give a cell crossing it twice
  CHECK(split.pieces.size() > whole.pieces.size());
  // The islands of a site add up to its whole piece.
  for (const auto& w : whole.pieces) {
    double s = 0;
    for (const auto& p : split.pieces)
      if (p.site_index == w.site_index) s += p.volume;
    CHECK(s == Approx(w.volume).epsilon(1e-12));
  }
}

TEST_CASE("sites: mesh vertices, given points, an impact point and jitter, all seeded") {
  const TriangleMesh torus = small_torus();
  FractureOptions o;
  o.pieces = 12;
  o.threads = 2;
  o.sites.source = SiteSource::mesh_vertices;
  const FractureResult mv = fracture_mesh(torus, o);
  check_islands(mv);
  for (const auto& p : mv.pieces)
    CHECK(std::find(torus.vertices.begin(), torus.vertices.end(), p.site) != torus.vertices.end());

  o.sites = {};
  o.sites.source = SiteSource::points;
  o.sites.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {5, 5, 5}};  // the last one outside
  const FractureResult given = fracture_mesh(torus, o);
  check_islands(given);
  CHECK(given.pieces.size() >= 4);
  CHECK(given.pieces[0].site == Point3{1, 0, 0});

  // Impact: the sites crowd around (1, 0, 0) (uniform sites in this torus lie ~1.1 away on average).
  o.sites = {};
  o.sites.impact = Point3{1, 0, 0};
  o.sites.impact_radius = 0.2;
  o.pieces = 20;
  const FractureResult imp = fracture_mesh(torus, o);
  check_islands(imp);
  double mean = 0;
  std::vector<std::int64_t> seen;
  for (const auto& p : imp.pieces)
    if (std::find(seen.begin(), seen.end(), p.site_index) == seen.end())
      seen.push_back(p.site_index), mean += norm(p.site - Point3{1, 0, 0});
  mean /= static_cast<double>(seen.size());
  CHECK(mean < 0.45);

  o.sites.noise = 0.02;
  const FractureResult a = fracture_mesh(torus, o), b = fracture_mesh(torus, o);
  REQUIRE(a.pieces.size() == b.pieces.size());
  for (std::size_t i = 0; i < a.pieces.size(); ++i) CHECK(a.pieces[i].site == b.pieces[i].site);
  CHECK_THROWS_AS([&] {
    FractureOptions bad = o;
    bad.sites.impact_radius = 0;
    fracture_mesh(torus, bad);
  }(), std::invalid_argument);
}

TEST_CASE("cell scale: stretched cells still tile the mesh") {
  TriangleMesh box;
  add_box(box, {0, 0, 0}, {1, 1, 1});
  FractureOptions o;
  o.pieces = 30;
  o.threads = 2;
  o.cell_scale = {1, 1, 5};
  const FractureResult r = fracture_mesh(box, o);
  check_islands(r);
  // Cut faces facing z (normal mostly along z) are rarer than with round cells.
  auto z_share = [](const FractureResult& fr) {
    double z = 0, all = 0;
    for (const auto& p : fr.pieces)
      for (std::size_t t = 0; t < p.geometry.mesh.triangles.size(); ++t) {
        if (!p.geometry.cut[t]) continue;
        const Point3 n = p.geometry.mesh.area_normal(t);
        z += std::abs(n.z), all += std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
      }
    return z / all;
  };
  o.cell_scale = {1, 1, 1};
  const FractureResult round = fracture_mesh(box, o);
  CHECK(z_share(r) < 0.5 * z_share(round));
}
