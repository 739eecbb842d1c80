#include <catch2/catch.hpp>

#include "voronoi/cell_check.hpp"
#include "voronoi/convex_cell.hpp"

using namespace dtlab;
using namespace dtlab::vor;

namespace {
// A view of the clipped cell; its arrays live in an arena kept for the whole test run.
VoronoiCell as_cell(const ConvexCell& c) {
  static CellArena arena;
  VoronoiCell out;
  out.vertices = arena.copy(std::span<const Point3>(c.vertices()));
  out.face_offsets = arena.copy(c.face_offsets());
  out.face_vertices = arena.copy(c.face_vertices());
  out.face_neighbor = arena.copy(c.face_tags());
  return out;
}
}  // namespace

TEST_CASE("a box cell is a closed cube with positive volume") {
  ConvexCell c;
  c.reset({{0, 0, 0}, {1, 2, 3}});
  CHECK(c.volume() == Approx(6).epsilon(1e-15));
  CHECK(check_cell(as_cell(c), 1e-12) == "");
  const Point3 m = c.centroid();
  CHECK(m.x == Approx(0.5));
  CHECK(m.y == Approx(1));
  CHECK(m.z == Approx(1.5));
}

TEST_CASE("a generic plane cut keeps a closed convex polytope of the right volume") {
  ConvexCell c;
  c.reset({{0, 0, 0}, {1, 1, 1}});
  // x + y + z <= 1: the corner tetrahedron, volume 1/6.
  CHECK(c.clip({1, 1, 1}, 1, 7, 1e-12));
  CHECK(c.volume() == Approx(1.0 / 6).epsilon(1e-14));
  CHECK(c.face_count() == 4);
  CHECK(check_cell(as_cell(c), 1e-12) == "");
  // A plane missing the cell changes nothing.
  CHECK_FALSE(c.clip({1, 0, 0}, 2, 8, 1e-12));
  // A plane through a vertex and an edge (x + y <= 1 touches the edge x+y=1,z=0) too.
  CHECK_FALSE(c.clip({1, 1, 0}, 1, 9, 1e-12));
}

TEST_CASE("planes through existing vertices and edges make no zero-length edges") {
  ConvexCell c;
  c.reset({{-1, -1, -1}, {1, 1, 1}});
  // x + y <= 0 passes through two box edges: cuts the box in half along a diagonal.
  REQUIRE(c.clip({1, 1, 0}, 0, 1, 1e-12));
  CHECK(c.volume() == Approx(4).epsilon(1e-14));
  CHECK(check_cell(as_cell(c), 1e-9) == "");
  CHECK_FALSE(has_edge_within(as_cell(c), 1e-9));
  CHECK(c.vertex_count() == 6);
  // x - y <= 0 through the same line x=y=0 (an edge of the new face).
  REQUIRE(c.clip({1, -1, 0}, 0, 2, 1e-12));
  CHECK(c.volume() == Approx(2).epsilon(1e-14));
  CHECK(check_cell(as_cell(c), 1e-9) == "");
  CHECK_FALSE(has_edge_within(as_cell(c), 1e-9));
  CHECK(c.vertex_count() == 6);
  // z <= 1 exactly on the top face: no cut.
  CHECK_FALSE(c.clip({0, 0, 1}, 1, 3, 1e-12));
  // A plane through the apex edge only (x <= 0 contains the edge x=y=0): no cut.
  CHECK_FALSE(c.clip({1, 0, 0}, 0, 4, 1e-12));
}

TEST_CASE("clipping everything away leaves an empty cell") {
  ConvexCell c;
  c.reset({{0, 0, 0}, {1, 1, 1}});
  c.clip({1, 0, 0}, -1, 1, 1e-12);
  CHECK(c.empty());
  CHECK(c.volume() == 0);
}
