// The exact Voronoi checker on several threads: the same report as on one (counts,
// witnesses in order, every measured number), and the same when the relation is read
// from our cells' DT instead of built, or shared by several checks.
#include <catch2/catch.hpp>

#include <limits>

#include "sites.hpp"

#include "voronoi_check/voronoi_check.hpp"

using namespace dtlab;

namespace {

using test::kBox;
using test::random_sites;

// Cells with defects spread over many chunks of sites and cells: every 97th cell has
// a vertex moved, every 131st loses its first face, every 173rd is left out.
ToolCells damaged(const ToolCells& t) {
  ToolCells out;
  for (std::size_t c = 0; c < t.size(); ++c) {
    if (c % 173 == 5) continue;
    const VoronoiCell v = t.cell(c);
    std::vector<Point3> vs(v.vertices.begin(), v.vertices.end());
    std::vector<std::uint32_t> fo(v.face_offsets.begin(), v.face_offsets.end());
    std::vector<std::uint32_t> fv(v.face_vertices.begin(), v.face_vertices.end());
    std::vector<std::int32_t> fn(v.face_neighbor.begin(), v.face_neighbor.end());
    if (c % 97 == 3) vs[0].x += 1e-3;
    if (c % 131 == 7) {
      const auto n = fo[1];
      fv.erase(fv.begin(), fv.begin() + n);
      fo.erase(fo.begin());
      for (auto& o : fo) o -= n;
      fn.erase(fn.begin());
    }
    out.add_cell(t.site(c), vs, fo, fv, fn);
  }
  return out;
}

void require_same(const VoronoiCheckReport& a, const VoronoiCheckReport& b) {
  CHECK(a.counts == b.counts);
  REQUIRE(a.witnesses.size() == b.witnesses.size());
  for (std::size_t k = 0; k < a.witnesses.size(); ++k) {
    CHECK(a.witnesses[k].kind == b.witnesses[k].kind);
    CHECK(a.witnesses[k].site == b.witnesses[k].site);
    CHECK(a.witnesses[k].neighbor == b.witnesses[k].neighbor);
    CHECK(a.witnesses[k].size == b.witnesses[k].size);
    CHECK(a.witnesses[k].detail == b.witnesses[k].detail);
  }
  CHECK(a.verdict == b.verdict);
  CHECK(a.topology == b.topology);
  CHECK(a.largest_wrong_face == b.largest_wrong_face);
  CHECK(a.largest_small_face == b.largest_small_face);
  CHECK(a.max_vertex_ulps == b.max_vertex_ulps);
  CHECK(a.max_vertex_error == b.max_vertex_error);
  CHECK(a.volume_sum == b.volume_sum);  // bitwise: the chunks are summed in order
  CHECK(a.faces == b.faces);
  CHECK(a.vertices == b.vertices);
  CHECK(a.voronoi_edges == b.voronoi_edges);
  CHECK(a.degenerate_edges == b.degenerate_edges);
}

VoronoiCheckReport check_on(const std::vector<Point3>& sites, const vor::Box& box, const ToolCells& cells,
                            unsigned threads, std::size_t witnesses = 3) {
  VoronoiCheckOptions o;
  o.threads = threads;
  o.witnesses_per_kind = witnesses;
  return check_voronoi(sites, box, cells, o);
}

}  // namespace

TEST_CASE("the check is the same on any thread count, defects and witnesses included", "[threads]") {
  const auto sites = random_sites(3000, 11);
  VoronoiOptions vo;
  vo.box = kBox;
  vo.threads = 1;
  const ToolCells cells = damaged(tool_cells_of(compute_voronoi(sites, vo)));
  const auto one = check_on(sites, kBox, cells, 1);
  INFO(voronoi_counts_text(one));
  REQUIRE(one.verdict == VoronoiVerdict::wrong_topology);
  REQUIRE(one.count(VoronoiDefect::vertex_off) > 3);  // more than kept: the cap meets the merge order
  REQUIRE(one.count(VoronoiDefect::missing_cell) > 3);
  REQUIRE(one.count(VoronoiDefect::missing_face) > 3);
  for (unsigned threads : {2u, 3u, 4u}) {
    INFO("threads " << threads);
    require_same(one, check_on(sites, kBox, cells, threads));
  }
}

TEST_CASE("the check is the same on any thread count on a lattice (exact, degenerate rings)", "[threads]") {
  std::vector<Point3> sites;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      for (int k = 0; k < 7; ++k) sites.push_back({double(i), double(j), double(k)});
  const vor::Box box{{-0.5, -0.5, -0.5}, {6.5, 6.5, 6.5}};
  VoronoiOptions vo;
  vo.box = box;
  vo.threads = 1;
  const ToolCells cells = tool_cells_of(compute_voronoi(sites, vo));
  const auto one = check_on(sites, box, cells, 1);
  REQUIRE(one.verdict == VoronoiVerdict::exact_topology);
  REQUIRE(one.degenerate_edges > 0);
  require_same(one, check_on(sites, box, cells, 3));
}

TEST_CASE("reading the relation from our cells' DT gives the same report as building it", "[threads]") {
  const auto sites = random_sites(2000, 12);
  VoronoiOptions vo;
  vo.box = kBox;
  vo.threads = 2;
  vo.keep_dt = true;
  const VoronoiDiagram vd = compute_voronoi(sites, vo);
  REQUIRE(vd.dt);
  const ToolCells cells = damaged(tool_cells_of(vd));
  VoronoiCheckOptions o;
  o.witnesses_per_kind = 3;
  const auto built = check_voronoi(sites, kBox, cells, o);
  o.dt = vd.dt;
  o.threads = 2;
  const auto read = check_voronoi(sites, kBox, cells, o);
  CHECK(read.seconds_dt == 0);
  require_same(built, read);
  // Without exact predicates the DT is not kept (the checker builds its own).
  vo.predicates.backend = "naive";
  CHECK_FALSE(compute_voronoi(sites, vo).dt);
}

TEST_CASE("one relation shared by the checks of several tools gives each the same report", "[threads]") {
  const auto sites = random_sites(2000, 13);
  VoronoiOptions vo;
  vo.box = kBox;
  const ToolCells whole = tool_cells_of(compute_voronoi(sites, vo));
  const ToolCells broken = damaged(whole);
  VoronoiCheckOptions o;
  o.witnesses_per_kind = 3;
  const auto whole_alone = check_voronoi(sites, kBox, whole, o);
  const auto broken_alone = check_voronoi(sites, kBox, broken, o);
  o.relation = voronoi_relation(sites, o);
  o.threads = 2;
  const auto broken_shared = check_voronoi(sites, kBox, broken, o);
  const auto whole_shared = check_voronoi(sites, kBox, whole, o);
  CHECK(whole_shared.seconds_dt == 0);
  CHECK(whole_shared.seconds_tables == 0);
  CHECK(whole_shared.verdict == VoronoiVerdict::exact_topology);
  CHECK(broken_shared.verdict == VoronoiVerdict::wrong_topology);
  require_same(whole_alone, whole_shared);
  require_same(broken_alone, broken_shared);
  // A relation of other sites is refused.
  CHECK_THROWS_AS(check_voronoi(random_sites(100, 1), kBox, whole, o), std::invalid_argument);
}

TEST_CASE("sites with no DT are refused on any thread count, the geometry beside the build or not", "[threads]") {
  // Coplanar sites, a non-finite one, none: the DT build (beside the cells' geometry from 2
  // threads on) throws, and the check rethrows it once both have finished.
  std::vector<Point3> flat;
  for (int i = 0; i < 40; ++i) flat.push_back({0.1 * (i % 7), 0.13 * (i / 7), 0.5});
  auto finite = random_sites(200, 3);
  VoronoiOptions vo;
  vo.box = kBox;
  const ToolCells cells = tool_cells_of(compute_voronoi(finite, vo));
  auto broken = finite;
  broken[17].y = std::numeric_limits<double>::quiet_NaN();
  for (unsigned threads : {1u, 2u, 4u}) {
    INFO("threads " << threads);
    VoronoiCheckOptions o;
    o.threads = threads;
    CHECK_THROWS_AS(check_voronoi(flat, kBox, cells, o), std::invalid_argument);
    CHECK_THROWS_AS(check_voronoi(broken, kBox, cells, o), std::invalid_argument);
    CHECK_THROWS_AS(check_voronoi({}, kBox, cells, o), std::invalid_argument);  // no site at all
  }
}
