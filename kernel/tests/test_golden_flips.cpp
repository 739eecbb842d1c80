// Golden flip tests: small hand-built inputs, inserted in input order with exact signs,
// each of which drives the inserter through one named flip sequence. Every case lists
// the flips it must take (BuildStats) and the tets it must end with (sorted vertex sets
// of input indices), so a change to one flip shows up here, in isolation, rather than
// as a wrong count somewhere in a campaign.
//
// Where the expected tets come from: for the general-position cases the Delaunay
// tetrahedralization is unique, and the lists were derived by brute force outside the
// kernel (every 4-subset whose circumsphere is empty, in rational arithmetic), which
// also confirmed that no 5 of the points are cospherical and no 4 coplanar. For the
// degenerate cases (perturb none) the triangulation is not unique: the list is the one
// the flips produce, and the test also proves it Delaunay (delaunay_check.hpp).
//
// Base of most cases: the corner tetrahedron o = (0,0,0), x = (8,0,0), y = (0,8,0),
// z = (0,0,8), inputs 0..3, whose circumsphere has centre (4,4,4) and radius^2 48.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <vector>

#include "delaunay_check.hpp"
#include "kernel/build.hpp"
#include "kernel/mesh_check.hpp"

using namespace dtlab;

namespace {

struct Flips {
  std::uint64_t f14, f23, f32, f44;
};

using TetSet = std::set<std::array<std::uint32_t, 4>>;

BuildResult build_in_order(const std::vector<Point3>& pts, bool perturb) {
  PredicateSpec spec;
  spec.backend = "exact";
  spec.perturb = perturb;
  BuildOptions opt;
  opt.order = InsertionOrder::input;
  opt.check_combinatorics = true;  // debug builds: the whole mesh checked after every flip
  return build_delaunay(pts, spec, opt);
}

TetSet sorted_tets(const BuildResult& r) {
  TetSet out;
  for (Tet t : r.mesh.tets) {
    std::sort(t.begin(), t.end());
    out.insert(t);
  }
  return out;
}

void require_golden(const std::vector<Point3>& pts, bool perturb, Flips flips, const TetSet& expected) {
  const BuildResult r = build_in_order(pts, perturb);
  REQUIRE_FALSE(r.failure);
  CHECK(r.stats.flips14 == flips.f14);
  CHECK(r.stats.flips23 == flips.f23);
  CHECK(r.stats.flips32 == flips.f32);
  CHECK(r.stats.flips44 == flips.f44);
  CHECK(sorted_tets(r) == expected);
  CHECK(test::validate(r).empty());
  // One check after each flip and one after each insertion (whose flip 1-4 is counted).
  const std::uint64_t checks = 2 * flips.f14 + flips.f23 + flips.f32 + flips.f44;
  CHECK(r.stats.mesh_checks == (kMeshChecksCompiled ? checks : 0));
}

const std::vector<Point3> kCorner = {{0, 0, 0}, {8, 0, 0}, {0, 8, 0}, {0, 0, 8}};

std::vector<Point3> corner_plus(std::initializer_list<Point3> more) {
  std::vector<Point3> pts = kCorner;
  pts.insert(pts.end(), more.begin(), more.end());
  return pts;
}

}  // namespace

TEST_CASE("golden 1-4: a point strictly inside the only tet splits it into four") {
  // (2,2,2) is inside oxyz; its four link facets are hull facets, so nothing flips.
  require_golden(corner_plus({{2, 2, 2}}), false, {1, 0, 0, 0},
                 {{0, 1, 2, 4}, {0, 1, 3, 4}, {0, 2, 3, 4}, {1, 2, 3, 4}});
}

TEST_CASE("golden 2-3: a point beyond a hull facet and inside the tet's circumsphere") {
  // p = (5,1,3) is beyond the facet xyz (x+y+z = 9 > 8) and at squared distance 11 < 48
  // from the centre: the 1-4 of the infinite tet on xyz makes the tet xyzp, whose facet
  // xyz is not locally Delaunay; segment op crosses triangle xyz, so one 2-3 replaces
  // oxyz and xyzp by the three tets around edge op.
  require_golden(corner_plus({{5, 1, 3}}), false, {1, 1, 0, 0}, {{0, 1, 2, 4}, {0, 1, 3, 4}, {0, 2, 3, 4}});
}

TEST_CASE("golden 2-3 then 3-2: the second point undoes an edge the first created") {
  require_golden(corner_plus({{3, 1, 2}, {2, 3, 2}}), false, {2, 1, 1, 0},
                 {{0, 1, 2, 5}, {0, 1, 3, 4}, {0, 1, 4, 5}, {0, 2, 3, 5}, {0, 3, 4, 5}, {1, 2, 3, 5}, {1, 3, 4, 5}});
}

TEST_CASE("golden degenerate: a point on an interior edge (flat tet, 2-3, 3-2)") {
  // (1,1,1) splits oxyz into four; (0.5,0.5,0.5) lies on the edge from o to (1,1,1),
  // shared by three of them. The 1-4 of the tet it is found in leaves two flat tets
  // (their four vertices on the line's planes); a 2-3 and a 3-2 remove them.
  require_golden(corner_plus({{1, 1, 1}, {0.5, 0.5, 0.5}}), false, {2, 1, 1, 0},
                 {{0, 1, 2, 5}, {0, 1, 3, 5}, {0, 2, 3, 5}, {1, 2, 3, 4}, {1, 2, 4, 5}, {1, 3, 4, 5}, {2, 3, 4, 5}});
}

TEST_CASE("golden degenerate: a point on an interior facet (flat tet removed by a 2-3)") {
  // (3,1,1) lies inside the triangle o, x, (2,2,2) shared by two of the four tets
  // around (2,2,2): the tet it is located in splits with one flat part.
  require_golden(corner_plus({{2, 2, 2}, {3, 1, 1}}), false, {2, 1, 0, 0},
                 {{0, 1, 2, 5},
                  {0, 1, 3, 5},
                  {0, 2, 3, 4},
                  {0, 2, 4, 5},
                  {0, 3, 4, 5},
                  {1, 2, 3, 4},
                  {1, 2, 4, 5},
                  {1, 3, 4, 5}});
}

TEST_CASE("golden 4-4: the segment from the new point crosses an edge of four tets") {
  // Integer points with coplanar quadruples (perturb none): the last point's segment to
  // the apex across a link facet passes through an edge, so the four tets around that
  // edge are replaced by the four around the new segment.
  const std::vector<Point3> pts = {{2, 2, 2}, {2, 1, 2}, {0, 0, 2}, {0, 0, 0}, {2, 2, 0}, {1, 2, 1}};
  require_golden(pts, false, {2, 1, 0, 1}, {{0, 1, 2, 5}, {0, 1, 4, 5}, {1, 2, 3, 5}, {1, 3, 4, 5}});
}

TEST_CASE("golden 4-4 under symbolic perturbation: insphere ties broken, orientation zeros kept") {
  // Perturbation decides the cospherical ties, not the coplanar ones (orient3d is not
  // perturbed), so the 4-4 is still taken; the ties send the flips another way first.
  const std::vector<Point3> pts = {{2, 2, 2}, {2, 1, 2}, {0, 0, 2}, {0, 0, 0}, {2, 2, 0}, {1, 2, 1}};
  require_golden(pts, true, {2, 2, 1, 1}, {{0, 1, 2, 5}, {0, 1, 4, 5}, {1, 2, 3, 5}, {1, 3, 4, 5}});
}
