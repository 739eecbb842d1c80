#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <random>

#include "tests/support/random_points.hpp"
#include "voronoi/cell_check.hpp"
#include "voronoi/circumcenter.hpp"
#include "voronoi/voronoi.hpp"
#include "voronoi/voronoi_io.hpp"
#include "voronoi/voronoi_range.hpp"

using namespace dtlab;
using namespace dtlab::vor;

namespace {

using test::uniform;

std::vector<Point3> lattice(int k, double h = 1) {
  std::vector<Point3> pts;
  for (int x = 0; x < k; ++x)
    for (int y = 0; y < k; ++y)
      for (int z = 0; z < k; ++z) pts.push_back({h * x, h * y, h * z});
  return pts;
}

const PredicateSpec kExact{"exact", 0, false, true};

void check_diagram(const VoronoiDiagram& vd, double volume_rel = 1e-12) {
  const double tol = 1e-9 * vd.box.diagonal();
  double sum = 0;
  for (std::size_t i = 0; i < vd.cells.size(); ++i) {
    const VoronoiCell& c = vd.cells[i];
    if (c.duplicate_of >= 0) continue;
    INFO("cell " << i);
    CHECK(check_cell(c, tol) == "");
    CHECK_FALSE(has_edge_within(c, tol));  // none of these inputs has a real edge that short
    CHECK(c.volume > 0);
    sum += c.volume;
    // Neighbour relation is symmetric.
    for (auto j : c.neighbors()) {
      auto nj = vd.cells[j].neighbors();
      CHECK(std::binary_search(nj.begin(), nj.end(), static_cast<std::uint32_t>(i)));
    }
  }
  CHECK(std::abs(sum - vd.box.volume()) <= volume_rel * vd.box.volume());
}

}  // namespace

TEST_CASE("random points: closed convex cells tile the box") {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    VoronoiOptions o;
    o.predicates = kExact;
    auto vd = compute_voronoi(uniform(300, seed), o);
    check_diagram(vd);
  }
}

TEST_CASE("interior Voronoi vertices are circumcentres of Delaunay tets") {
  auto pts = uniform(200, 11);
  VoronoiOptions o;
  o.predicates = kExact;
  o.margin = 2;  // large box: most cells are not touched by it
  auto vd = compute_voronoi(pts, o);
  auto dt = build_delaunay(pts, kExact);
  REQUIRE_FALSE(dt.failure);
  std::vector<Point3> cc;
  for (const auto& t : dt.mesh.tets) cc.push_back(circumcenter(pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]]));
  std::size_t checked = 0;
  for (const auto& c : vd.cells) {
    if (std::any_of(c.face_neighbor.begin(), c.face_neighbor.end(), [](int t) { return t < 0; })) continue;
    for (const auto& v : c.vertices) {
      double best = INFINITY;
      for (const auto& q : cc) best = std::min(best, norm(q - v));
      CHECK(best < 1e-9);
      ++checked;
    }
  }
  CHECK(checked > 100);
}

TEST_CASE("circumcenter is equidistant and reports bad conditioning of flat tets") {
  Point3 a{1, 0, 0}, b{0, 1, 0}, c{0, 0, 1}, d{0.3, 0.2, 0.1};
  double cond = 0;
  Point3 o = circumcenter(a, b, c, d, &cond);
  const double r = norm(a - o);
  CHECK(norm(b - o) == Approx(r).epsilon(1e-14));
  CHECK(norm(c - o) == Approx(r).epsilon(1e-14));
  CHECK(norm(d - o) == Approx(r).epsilon(1e-14));
  double flat = 0;
  circumcenter({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1e-9}, &flat);
  CHECK(flat > 1e8 * cond);
}

TEST_CASE("cospherical lattice: coincident Voronoi vertices merge into exact cubes") {
  auto pts = lattice(5);
  VoronoiOptions o;
  o.predicates = kExact;
  o.box = Box{{-0.5, -0.5, -0.5}, {4.5, 4.5, 4.5}};
  auto vd = compute_voronoi(pts, o);
  check_diagram(vd);
  for (const auto& c : vd.cells) {
    CHECK(c.vertices.size() == 8);
    CHECK(c.face_count() == 6);
    CHECK(c.volume == Approx(1).epsilon(1e-14));
  }
  // Default box: boundary cells are longer boxes, still cubes' worth of faces.
  o.box.reset();
  check_diagram(compute_voronoi(pts, o));
}

TEST_CASE("cospherical inputs: points on a sphere and a perturbed lattice") {
  // Octahedron + cube vertices on the unit sphere, plus the centre.
  std::vector<Point3> pts{{0, 0, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const double s = 1 / std::sqrt(3.0);
  for (int k = 0; k < 8; ++k) pts.push_back({(k & 1) ? s : -s, (k & 2) ? s : -s, (k & 4) ? s : -s});
  VoronoiOptions o;
  o.predicates = kExact;
  check_diagram(compute_voronoi(pts, o));
  // Body-centred cubic lattice: truncated octahedra, with 4 cospherical sites per vertex.
  auto bcc = lattice(4, 2);
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) bcc.push_back({2.0 * x + 1, 2.0 * y + 1, 2.0 * z + 1});
  auto vd = compute_voronoi(bcc, o);
  check_diagram(vd);
  // The centre site (1+2,1+2,1+2 = index 64 + 13) is a truncated octahedron: 14 faces, 24 vertices.
  const auto& mid = vd.cells[64 + 13];
  CHECK(mid.face_count() == 14);
  CHECK(mid.vertices.size() == 24);
  CHECK(mid.volume == Approx(4).epsilon(1e-13));
}

TEST_CASE("duplicates get an empty cell; coplanar and tiny inputs still work") {
  auto pts = uniform(50, 3);
  pts.push_back(pts[7]);
  VoronoiOptions o;
  o.predicates = kExact;
  auto vd = compute_voronoi(pts, o);
  CHECK(vd.cells.back().duplicate_of == 7);
  CHECK(vd.cells.back().vertices.empty());
  check_diagram(vd);
  // Coplanar sites: prisms through the box.
  std::vector<Point3> flat;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 30; ++i) flat.push_back({u(rng), u(rng), 0});
  check_diagram(compute_voronoi(flat, o));
  // A single site owns the whole box; two sites split it by their bisector.
  auto one = compute_voronoi(std::vector<Point3>{{0, 0, 0}}, o);
  CHECK(one.cells[0].volume == Approx(one.box.volume()));
  check_diagram(compute_voronoi(std::vector<Point3>{{0, 0, 0}, {1, 1, 1}}, o));
}

TEST_CASE("manifest totals and OBJ/VTU writers") {
  auto pts = uniform(40, 9);
  VoronoiOptions o;
  o.predicates = kExact;
  auto vd = compute_voronoi(pts, o);
  auto m = cells_manifest(vd);
  CHECK(m["cells"].size() == 40);
  CHECK(m["cell_volume_sum"].get<double>() == Approx(m["box_volume"].get<double>()).epsilon(1e-12));
  const std::string dir = std::filesystem::temp_directory_path().string();
  write_cells_obj(dir + "/voronoi_test_cells.obj", vd);
  write_cells_vtu(dir + "/voronoi_test_cells.vtu", vd);
  std::FILE* f = std::fopen((dir + "/voronoi_test_cells.obj").c_str(), "r");
  REQUIRE(f);
  int groups = 0;
  char line[256];
  while (std::fgets(line, sizeof line, f))
    if (line[0] == 'g') ++groups;
  std::fclose(f);
  CHECK(groups == 40);
}

TEST_CASE("dual cells agree with the clipping engine; shrink and threads") {
  auto pts = uniform(400, 21);
  VoronoiOptions o;
  o.predicates = kExact;
  o.threads = 2;
  auto vd = compute_voronoi(pts, o);
  check_diagram(vd);
  // Most cells come from the DT directly; hull sites are clipped.
  CHECK(vd.clipped < pts.size() / 2);
  CHECK(vd.clipped > 0);
  auto dt = build_delaunay(pts, kExact);
  REQUIRE_FALSE(dt.failure);
  const Adjacency adj = delaunay_neighbors(dt.mesh);
  ConvexCell cell;
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    compute_cell(cell, pts, i, {adj.adj.data() + adj.off[i], adj.off[i + 1] - adj.off[i]}, vd.box, 1e-12, vd.scale);
    INFO("cell " << i);
    CHECK(std::abs(cell.volume() - vd.cells[i].volume) <= 1e-12 * vd.box.volume());
    CHECK(cell.face_count() == vd.cells[i].face_count());
  }
  // Shrunk cells (gaps between neighbours) lie inside the plain ones.
  o.shrink = 0.01;
  auto shrunk = compute_voronoi(pts, o);
  CHECK(shrunk.clipped == pts.size());
  double sum = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    CHECK(shrunk.cells[i].volume < vd.cells[i].volume);
    sum += shrunk.cells[i].volume;
  }
  CHECK(sum < 0.99 * vd.box.volume());
}

TEST_CASE("a box 1e10 to 1e100 times the sites: the cells are the sites' own (cell_scale)") {
  // docs/probe3.md: with tolerances of the box diagonal (a band of 0.035 at 1e10) the
  // cells of 200 sites in the unit cube lost faces; at 1e30 they had no volume.
  const auto pts = uniform(200, 11, 0, 1);
  VoronoiOptions o;
  o.predicates = kExact;
  const VoronoiDiagram near = compute_voronoi(pts, o);
  for (double b : {1e10, 1e30, 1e100}) {
    INFO("box +-" << b);
    o.box = Box{{-b, -b, -b}, {b, b, b}};
    const VoronoiDiagram vd = compute_voronoi(pts, o);
    CHECK(vd.scale == Approx(default_box(pts, 0.1).diagonal()));
    CHECK(lost_cells_problem(vd).empty());
    const double floor = cells_rounding_floor(vd, false).vertex_error;
    std::size_t bounded = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      INFO("cell " << i);
      CHECK(check_cell(vd.cells[i], 1e-9 * vd.scale, floor) == "");
      // A cell the default box does not clip is bounded: the same cell in any box.
      const auto& walls = near.cells[i].face_neighbor;
      if (std::any_of(walls.begin(), walls.end(), [](std::int32_t t) { return t < 0; })) continue;
      ++bounded;
      CHECK(vd.cells[i].neighbors() == near.cells[i].neighbors());
      CHECK(vd.cells[i].volume == Approx(near.cells[i].volume).epsilon(1e-12));
    }
    CHECK(bounded > 40);
  }
}

TEST_CASE("cospherical sites in a box 1e10 times their size: closed cells (the redo in the box's band)") {
  // 100 sites on a golden-angle spiral of the unit sphere: the exact corners at the
  // centre lie ~1e-17 apart and round together, the band of the sites' scale is below the
  // far vertices' rounding, so neither cell survives: the cell is redone in the box
  // diagonal's band (without it two cells had a directed edge twice).
  std::vector<Point3> pts;
  for (int k = 0; k < 100; ++k) {
    const double z = 0.99 - 0.02 * k, r = std::sqrt(1 - z * z), phi = 2.399963 * k;
    pts.push_back({r * std::cos(phi), r * std::sin(phi), z});
  }
  VoronoiOptions o;
  o.predicates = kExact;
  for (double b : {1e10, 1e30}) {
    INFO("box +-" << b);
    o.box = Box{{-b, -b, -b}, {b, b, b}};
    const VoronoiDiagram vd = compute_voronoi(pts, o);
    CHECK(lost_cells_problem(vd).empty());
    const double floor = cells_rounding_floor(vd, false).vertex_error;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      INFO("cell " << i);
      CHECK(check_cell(vd.cells[i], 1e-9 * vd.scale, floor) == "");
    }
  }
}

TEST_CASE("voronoi_refusal: the sites' range first, then the box's, given or grown", "[voronoi][range]") {
  const std::vector<Point3> ok = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Box unit{{-1, -1, -1}, {2, 2, 2}}, huge{{-1, -1, -1}, {2e101, 2, 2}};
  CHECK_FALSE(voronoi_refusal(ok, std::nullopt, 0.1));
  CHECK_FALSE(voronoi_refusal(ok, unit, 0.1));
  const auto given = voronoi_refusal(ok, huge, 0.1);
  REQUIRE(given);
  CHECK(given->range == VoronoiRefusal::Range::box);
  CHECK(given->reason.rfind("--box: corners beyond 1e101", 0) == 0);
  const auto grown = voronoi_refusal(ok, std::nullopt, 1e102);
  REQUIRE(grown);
  CHECK(grown->range == VoronoiRefusal::Range::box);
  CHECK(grown->reason.rfind("--margin 1e+102 grows the sites' bounding box beyond 1e101", 0) == 0);
  std::vector<Point3> far = ok;
  far.push_back({2e100, 0, 0});
  const auto sites = voronoi_refusal(far, huge, 0.1);  // both out of range: the sites named
  REQUIRE(sites);
  CHECK(sites->range == VoronoiRefusal::Range::sites);
  CHECK(sites->reason.find("beyond 1e100") != std::string::npos);
  const std::vector<Point3> tiny = {{0, 0, 0}, {1e-101, 0, 0}, {0, 1e-101, 0}, {0, 0, 1e-101}};
  const auto span = voronoi_refusal(tiny, std::nullopt, 0.1);
  REQUIRE(span);
  CHECK(span->range == VoronoiRefusal::Range::sites);
  CHECK(span->reason.find("less than 1e-100") != std::string::npos);
}
