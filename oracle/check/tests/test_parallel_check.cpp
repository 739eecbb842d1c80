// The exact checker on several threads gives the serial checker's report, witness for
// witness: on valid meshes (uniform, lattice with cospherical cells, points on one
// sphere) and on broken ones (a flipped tet, a moved vertex, a dropped tet, a
// duplicated tet), at 1, 2, 3, 4 and 8 threads; and the facet table and edge count
// alone, large enough that every pass splits into many bucket ranges.
#include <catch2/catch.hpp>

#include <random>

#include "kernel/build.hpp"
#include "oracle/check/check.hpp"
#include "oracle/check/facet_table.hpp"
#include "oracle/check/tests/point_sets.hpp"

using namespace dtlab;

namespace {

Tetrahedralization built(std::vector<Point3> pts) {
  BuildResult r = build_delaunay(std::move(pts), PredicateSpec{}, BuildOptions{});
  REQUIRE_FALSE(r.failure);
  return std::move(r.mesh);
}

// Broken copies of a valid mesh, each with a different kind of defect.
std::vector<Tetrahedralization> broken_copies(const Tetrahedralization& t) {
  std::vector<Tetrahedralization> out(4, t);
  std::swap(out[0].tets[7][0], out[0].tets[7][1]);                                // inverted
  out[1].points[t.tets[3][2]].x += 0.01;                                          // non-Delaunay, maybe more
  out[2].tets.erase(out[2].tets.begin() + static_cast<long>(t.tets.size() / 2));  // a hole
  out[3].tets.push_back(t.tets[11]);                                              // a facet in 3+ tets
  return out;
}

void require_same(const CheckReport& a, const CheckReport& b) {
  CHECK(a.counts == b.counts);
  REQUIRE(a.defects.size() == b.defects.size());
  for (std::size_t i = 0; i < a.defects.size(); ++i) {
    CHECK(a.defects[i].kind == b.defects[i].kind);
    CHECK(a.defects[i].tets == b.defects[i].tets);
    CHECK(a.defects[i].vertices == b.defects[i].vertices);
    CHECK(a.defects[i].sign == b.defects[i].sign);
    CHECK(a.defects[i].detail == b.defects[i].detail);
  }
  CHECK(a.cospherical_pairs == b.cospherical_pairs);
  CHECK(a.stats.interior_facets == b.stats.interior_facets);
  CHECK(a.stats.boundary_facets == b.stats.boundary_facets);
  CHECK(a.stats.edges == b.stats.edges);
  CHECK(a.stats.euler == b.stats.euler);
  CHECK(a.stats.cover_proven == b.stats.cover_proven);
  CHECK(a.stats.volume_hull == b.stats.volume_hull);
}

void require_same_at_every_thread_count(const Tetrahedralization& t) {
  CheckOptions serial;
  serial.witnesses_per_kind = 1000;
  const CheckReport want = check_tetrahedralization(t, serial);
  for (unsigned threads : {2u, 3u, 4u, 8u}) {
    INFO("threads " << threads);
    CheckOptions o = serial;
    o.threads = threads;
    require_same(check_tetrahedralization(t, o), want);
    require_same(check_tetrahedralization(Tetrahedralization(t), o),
                 check_tetrahedralization(Tetrahedralization(t), serial));
  }
}

}  // namespace

TEST_CASE("parallel checker: valid meshes, the serial report at every thread count", "[check][threads]") {
  for (auto pts : {test::uniform_points(3000, 5), test::lattice_points(9), test::sphere_points(50)}) {
    const Tetrahedralization t = built(pts);
    INFO(t.points.size() << " points");
    CheckOptions o;
    o.threads = 4;
    REQUIRE(check_tetrahedralization(t, o).ok());
    require_same_at_every_thread_count(t);
  }
}

TEST_CASE("parallel checker: broken meshes, the same witnesses in the same order", "[check][threads]") {
  const Tetrahedralization t = built(test::uniform_points(2000, 9));
  for (const Tetrahedralization& b : broken_copies(t)) {
    CheckOptions o;
    o.threads = 3;
    REQUIRE_FALSE(check_tetrahedralization(b, o).ok());
    require_same_at_every_thread_count(b);
  }
}

TEST_CASE("parallel facet table and edge count equal the serial ones", "[check][threads]") {
  // Over 2^20 entries: several passes, each split into bucket ranges.
  const Tetrahedralization t = built(test::uniform_points(60000, 3));
  const std::vector<std::uint32_t> rank = first_appearance(t.tets, t.points.size());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> serial_pairs, parallel_pairs;
  auto classify = [](const FacetPair& f) { return (f.r1 ^ f.r2) % 7 == 0 ? 1 + int(f.odd1) : 0; };
  const FacetTable a = build_facet_table(
      t.tets, rank, classify, [&](const FacetPair& f, int c) { serial_pairs.emplace_back(f.r1, f.r2 + c); }, 1);
  const FacetTable b = build_facet_table(
      t.tets, rank, classify, [&](const FacetPair& f, int c) { parallel_pairs.emplace_back(f.r1, f.r2 + c); }, 4);
  CHECK(a.boundary_refs == b.boundary_refs);
  CHECK(a.interior == b.interior);
  CHECK(a.boundary == b.boundary);
  CHECK(a.same_side.empty());
  CHECK(b.same_side.empty());
  CHECK(serial_pairs.size() > 1000);
  CHECK(serial_pairs == parallel_pairs);
  const std::uint64_t edges = count_edges(t.tets, rank, 1);
  CHECK(count_edges(t.tets, rank, 2) == edges);
  CHECK(count_edges(t.tets, rank, 5) == edges);
  // 64 workers: a mark array each (4 bytes a point) would cost more than the pass's
  // entries (about 6 per tet), so the workers sort and dedupe their buckets instead.
  REQUIRE(64 * t.points.size() > 7 * t.tets.size());
  CHECK(count_edges(t.tets, rank, 64) == edges);
  // Euler: V - E + F - T = 1 for a ball.
  CHECK(std::int64_t(t.points.size()) - std::int64_t(edges) + std::int64_t(a.interior + a.boundary) -
            std::int64_t(t.tets.size()) ==
        1);
}
