#include <catch2/catch.hpp>

#include <algorithm>
#include <map>

#include "fracture/fracture.hpp"
#include "fracture/piece_io.hpp"
#include "sampling/bumpy_torus.hpp"

using namespace dtlab;

namespace {

TriangleMesh cube(double s = 1) {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k) m.vertices.push_back({(k & 1) ? s : 0, (k & 2) ? s : 0, (k & 4) ? s : 0});
  const std::uint32_t q[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (auto& f : q) {
    m.triangles.push_back({f[0], f[1], f[2]});
    m.triangles.push_back({f[0], f[2], f[3]});
  }
  return m;
}

TriangleMesh icosphere(int levels) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  TriangleMesh m;
  m.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  m.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (auto& v : m.vertices) v = (1.0 / norm(v)) * v;
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto middle = [&](std::uint32_t a, std::uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      Point3 p = m.vertices[a] + m.vertices[b];
      m.vertices.push_back((1.0 / norm(p)) * p);
      return mid[key] = static_cast<std::uint32_t>(m.vertices.size() - 1);
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    for (auto [a, b, c] : m.triangles) {
      auto ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      next.push_back({a, ab, ca});
      next.push_back({b, bc, ab});
      next.push_back({c, ca, bc});
      next.push_back({ab, bc, ca});
    }
    m.triangles = next;
  }
  return m;
}

// Closed and manifold along edges: every directed edge once, its reverse once.
bool closed_manifold(const TriangleMesh& m) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> e;
  for (auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) e.push_back({t[k], t[(k + 1) % 3]});
  std::sort(e.begin(), e.end());
  if (std::adjacent_find(e.begin(), e.end()) != e.end()) return false;
  for (auto [a, b] : e)
    if (a == b || !std::binary_search(e.begin(), e.end(), std::pair{b, a})) return false;
  return !m.triangles.empty();
}

void check_fracture(const FractureResult& r, std::size_t at_least) {
  REQUIRE(r.pieces.size() >= at_least);
  double sum = 0;
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    const Piece& p = r.pieces[i];
    INFO("piece " << i);
    CHECK(closed_manifold(p.geometry.mesh));
    CHECK(p.volume > 0);
    sum += p.volume;
    for (auto j : p.neighbors) {
      CHECK(j != i);
      const auto& nj = r.pieces[j].neighbors;
      CHECK(std::find(nj.begin(), nj.end(), i) != nj.end());
    }
  }
  CHECK(std::abs(sum - r.mesh_volume) <= 1e-9 * r.mesh_volume);
}

}  // namespace

TEST_CASE("a cube fractures into closed pieces whose volumes sum to the cube's") {
  FractureOptions o;
  o.pieces = 12;
  o.seed = 3;
  auto r = fracture_mesh(cube(), o);
  CHECK(r.mesh_volume == Approx(1).epsilon(1e-14));
  check_fracture(r, 12);
  for (const auto& p : r.pieces) {
    CHECK(p.interior_area > 0);  // every piece of a 12-piece cube has a cut face
    CHECK_FALSE(p.neighbors.empty());
  }
  auto m = fracture_manifest(r);
  CHECK(m["relative_volume_error"].get<double>() < 1e-9);
}

TEST_CASE("an icosphere and a small bumpy torus fracture exactly") {
  FractureOptions o;
  o.pieces = 10;
  o.seed = 7;
  check_fracture(fracture_mesh(icosphere(2), o), 10);
  BumpyTorusParams bp;
  bp.nu = 32;
  bp.nv = 16;
  o.pieces = 8;
  check_fracture(fracture_mesh(make_bumpy_torus(bp), o), 8);
}

TEST_CASE("many pieces: cells inside the mesh skip the boolean") {
  FractureOptions o;
  o.pieces = 150;
  o.seed = 2;
  auto r = fracture_mesh(cube(), o);
  check_fracture(r, 150);
  CHECK(r.skipped > 0);
  CHECK(r.booleans > 0);
}

TEST_CASE("margin leaves gaps; recursion splits chosen pieces further") {
  FractureOptions o;
  o.pieces = 6;
  o.seed = 5;
  o.margin = 0.02;
  auto r = fracture_mesh(cube(), o);
  double sum = 0;
  for (const auto& p : r.pieces) {
    CHECK(closed_manifold(p.geometry.mesh));
    sum += p.volume;
  }
  CHECK(sum < 0.99);
  CHECK(sum > 0.8);

  FractureOptions rec;
  rec.pieces = 5;
  rec.seed = 5;
  rec.recurse = {0, 2};
  rec.recurse_pieces = 3;
  auto rr = fracture_mesh(cube(), rec);
  check_fracture(rr, 5 - 2 + 2 * 2);
  std::size_t children = 0;
  for (const auto& p : rr.pieces) children += p.parent >= 0;
  CHECK(children >= 4);
}

TEST_CASE("open or non-manifold input is refused with a reason") {
  TriangleMesh open = cube();
  open.triangles.pop_back();
  FractureOptions o;
  CHECK_THROWS_WITH(fracture_mesh(open, o), Catch::Contains("not closed"));
  TriangleMesh none;
  CHECK_THROWS(fracture_mesh(none, o));
}

TEST_CASE("box-split booleans give the same pieces as whole-mesh booleans") {
  // 70 cells: the cells are split into boxes (more than 16 per leaf) before the
  // per-cell corefinements; each piece must match the corefinement with the whole mesh.
  BumpyTorusParams bp;
  bp.nu = 48;
  bp.nv = 24;
  const TriangleMesh torus = make_bumpy_torus(bp);
  FractureOptions o;
  o.pieces = 70;
  o.seed = 4;
  o.threads = 2;
  auto r = fracture_mesh(torus, o);
  check_fracture(r, 40);
  MeshClipper clipper(torus);
  MeshSampler sampler(clipper.mesh());
  SampleRequest req;
  req.count = 70;
  req.seed = 4;
  const auto sites = sampler.sample(req).points;
  VoronoiOptions vo;
  Box3 mb = bounding_box(clipper.mesh());
  vo.box = vor::Box{mb.lo - 0.05 * mb.extent(), mb.hi + 0.05 * mb.extent()};
  const VoronoiDiagram vd = compute_voronoi(sites, vo);
  const auto split = clipper.intersect_all(vd.cells, 2);
  REQUIRE(split.size() == vd.cells.size());
  double total = 0;
  for (std::size_t i = 0; i < vd.cells.size(); ++i) {
    INFO("cell " << i);
    Piece a, b;
    a.geometry = split[i];
    b.geometry = clipper.intersect(vd.cells[i]);
    CHECK(a.geometry.mesh.triangles.empty() == b.geometry.mesh.triangles.empty());
    if (b.geometry.mesh.triangles.empty()) continue;
    CHECK(closed_manifold(a.geometry.mesh));
    measure_piece(a);
    measure_piece(b);
    CHECK(std::abs(a.volume - b.volume) <= 1e-12 * clipper.volume());
    CHECK(std::abs(a.interior_area - b.interior_area) <= 1e-9 * b.interior_area);
    total += a.volume;
  }
  CHECK(std::abs(total - clipper.volume()) <= 1e-9 * clipper.volume());
}
