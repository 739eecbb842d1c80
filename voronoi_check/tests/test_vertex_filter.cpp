// The vertex test's double filter (voronoi_check/vertex_filter.hpp): wherever it gives
// a bound, the long double solve's distance lies below it, on cells whose vertices are
// exact to a few ulps, moved by many ulps, or far off, on uniform and on degenerate and
// badly conditioned families; and vertex_errors with a threshold computes the same
// distances as without, skipping only vertices certified below it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "fuzz/families.hpp"
#include "sites.hpp"
#include "voronoi_check/cell_geometry.hpp"
#include "voronoi_check/tool_cells.hpp"
#include "voronoi_check/vertex_filter.hpp"

using namespace dtlab;

namespace {

// Cells with each vertex coordinate moved by up to `ulps` ulps (`ulps` 0: as computed).
ToolCells moved(const VoronoiDiagram& vd, int ulps, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> k(-ulps, ulps);
  const auto nudge = [&](double x) { return x + k(rng) * (std::nextafter(std::abs(x), INFINITY) - std::abs(x)); };
  ToolCells out;
  for (std::size_t s = 0; s < vd.cells.size(); ++s) {
    const VoronoiCell& c = vd.cells[s];
    if (c.face_count() == 0 ||
        std::any_of(c.vertices.begin(), c.vertices.end(), [](const Point3& p) { return !is_finite(p); }))
      continue;
    std::vector<Point3> vs(c.vertices.begin(), c.vertices.end());
    for (auto& p : vs) p = {nudge(p.x), nudge(p.y), nudge(p.z)};
    out.add_cell(static_cast<std::int64_t>(s), vs, c.face_offsets, c.face_vertices, c.face_neighbor);
  }
  return out;
}

struct Tally {
  std::size_t bounded = 0, simple = 0, skipped = 0, batched = 0;
};

// Every vertex on exactly three faces: the filter's bound against the long double distance.
void check_cells(std::span<const Point3> sites, const vor::Box& box, const ToolCells& t, Tally& tally) {
  std::vector<VertexError> exact, filtered;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const VoronoiCell c = t.view(k);
    const auto site = static_cast<std::uint32_t>(t.site(k));
    exact.resize(c.vertices.size());
    vertex_errors(c, sites, site, box, exact);
    std::vector<std::vector<std::size_t>> at(c.vertices.size());
    for (std::size_t f = 0; f < c.face_count(); ++f)
      for (auto i = c.face_offsets[f]; i < c.face_offsets[f + 1]; ++i) at[c.face_vertices[i]].push_back(f);
    double largest = 0;
    BoundBatch batch;
    batch.start();
    std::vector<double> one_by_one;
    for (std::size_t v = 0; v < c.vertices.size(); ++v) {
      if (at[v].size() != 3) continue;
      ++tally.simple;
      FilterPlane pl[3];
      bool ok = true;
      for (int i = 0; i < 3; ++i) ok &= filter_plane(c.face_neighbor[at[v][i]], sites, sites[site], box, pl[i]);
      if (!ok) continue;
      const double u = vertex_distance_bound(c.vertices[v], sites[site], pl[0], pl[1], pl[2]);
      REQUIRE(batch.add(c.vertices[v], sites[site], pl[0], pl[1], pl[2]));
      one_by_one.push_back(u);
      if (u < 0) continue;
      ++tally.bounded;
      INFO("cell " << k << " vertex " << v << " bound " << u << " distance " << exact[v].distance);
      REQUIRE(exact[v].decided);
      REQUIRE(exact[v].distance <= u);
      largest = std::max(largest, exact[v].distance);
    }
    // The batch (several lanes per instruction) gives every bound bit for bit, -1 included.
    std::vector<double> batched(batch.size());
    batch.bounds(batched);
    REQUIRE(batched.size() == one_by_one.size());
    for (std::size_t i = 0; i < batched.size(); ++i)
      REQUIRE(std::bit_cast<std::uint64_t>(batched[i]) == std::bit_cast<std::uint64_t>(one_by_one[i]));
    tally.batched += batched.size();
    // With the cell's own largest distance as the threshold: the same numbers.
    filtered.resize(c.vertices.size());
    vertex_errors(c, sites, site, box, filtered, largest);
    for (std::size_t v = 0; v < c.vertices.size(); ++v) {
      REQUIRE(filtered[v].decided == exact[v].decided);
      if (filtered[v].below) {
        ++tally.skipped;
        REQUIRE(exact[v].distance <= largest);
      } else {
        REQUIRE(filtered[v].distance == exact[v].distance);
      }
    }
  }
}

}  // namespace

TEST_CASE("vertex filter: the bound lies above the long double distance on uniform sites", "[vertex-filter]") {
  const auto sites = test::random_sites(1500, 5);
  VoronoiOptions o;
  o.box = test::kBox;
  o.threads = 1;
  const auto vd = compute_voronoi(sites, o);
  for (int ulps : {0, 4, 64, 1 << 20}) {
    Tally tally;
    check_cells(sites, test::kBox, moved(vd, ulps, 7), tally);
    INFO("ulps " << ulps);
    CHECK(tally.simple > 10000);
    CHECK(tally.bounded > tally.simple * 9 / 10);  // nearly every vertex of uniform sites
    CHECK(tally.skipped > 0);
    CHECK(tally.batched == tally.simple);
  }
}

TEST_CASE("vertex filter: a full batch refuses a lane", "[vertex-filter]") {
  const std::vector<Point3> sites{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  FilterPlane pl[3];
  for (int i = 0; i < 3; ++i) REQUIRE(filter_plane(i + 1, sites, sites[0], test::kBox, pl[i]));
  BoundBatch batch;
  batch.start();
  const Point3 corner{0.5, 0.5, 0.5};
  for (std::size_t k = 0; k < BoundBatch::kLanes; ++k) REQUIRE(batch.add(corner, sites[0], pl[0], pl[1], pl[2]));
  CHECK_FALSE(batch.add(corner, sites[0], pl[0], pl[1], pl[2]));
  std::vector<double> out(batch.size());
  batch.bounds(out);
  CHECK(out == std::vector<double>(BoundBatch::kLanes, vertex_distance_bound(corner, sites[0], pl[0], pl[1], pl[2])));
  CHECK(out[0] >= 0);
  CHECK(out[0] < 1e-14);  // the corner is where the three bisectors meet, exactly
  batch.start();          // emptied
  CHECK(batch.size() == 0);
  CHECK(batch.add(corner, sites[0], pl[0], pl[1], pl[2]));
}

TEST_CASE("vertex filter: degenerate and badly conditioned families", "[vertex-filter]") {
  Tally all;
  for (const char* name : {"clustered", "near_degenerate", "lattice_subset", "moment_curve", "extreme_scale",
                           "far_translate", "cospherical", "ulp_jitter"}) {
    const fuzz::Family* f = fuzz::find_family(name);
    REQUIRE(f);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const auto sites = f->generate(300, seed);
      VoronoiOptions o;
      o.threads = 1;
      VoronoiDiagram vd;
      try {
        vd = compute_voronoi(sites, o);
      } catch (const std::exception&) {
        continue;  // coplanar or out of range: no cells to test
      }
      INFO(name << " seed " << seed);
      check_cells(sites, vd.box, moved(vd, 2, seed), all);
    }
  }
  // Both paths taken: bounds given, and vertices left to the long double solve.
  CHECK(all.bounded > 0);
  CHECK(all.bounded < all.simple);
}

TEST_CASE("vertex filter: a cell of more vertices than a batch holds is filtered block by block", "[vertex-filter]") {
  // A site inside 400 sites spread over a sphere: its cell has about 800 vertices.
  std::vector<Point3> sites{{0, 0, 0}};
  const int k = 400;
  for (int i = 0; i < k; ++i) {
    const double z = 1 - (2 * i + 1.0) / k, r = std::sqrt(1 - z * z), phi = 2.399963229728653 * i;
    sites.push_back({r * std::cos(phi), r * std::sin(phi), z});
  }
  const vor::Box box{{-2, -2, -2}, {2, 2, 2}};
  VoronoiOptions o;
  o.box = box;
  const auto vd = compute_voronoi(sites, o);
  // Vertices moved by up to 2^20 ulps: distances well above the filter's own error
  // (the neighbours' directions are close, so the planes' meets are conditioned badly).
  const ToolCells t = moved(vd, 1 << 20, 3);
  REQUIRE(t.site(0) == 0);
  const VoronoiCell c = t.view(0);
  REQUIRE(c.vertices.size() > 2 * BoundBatch::kLanes);
  std::vector<VertexError> exact(c.vertices.size()), filtered(c.vertices.size());
  vertex_errors(c, sites, 0, box, exact);
  double largest = 0;
  for (const auto& e : exact) largest = std::max(largest, e.decided ? e.distance : 0);
  vertex_errors(c, sites, 0, box, filtered, largest);
  std::size_t skipped = 0, late = 0;  // late: skipped beyond the first block
  for (std::size_t v = 0; v < c.vertices.size(); ++v) {
    INFO("vertex " << v);
    REQUIRE(filtered[v].decided == exact[v].decided);
    if (filtered[v].below) {
      ++skipped, late += v >= BoundBatch::kLanes;
      REQUIRE(exact[v].distance <= largest);
    } else {
      REQUIRE(filtered[v].distance == exact[v].distance);
    }
  }
  CHECK(late > 0);
  CHECK(skipped > c.vertices.size() / 2);
}
