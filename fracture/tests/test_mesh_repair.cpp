#include <catch2/catch.hpp>

#include <algorithm>

#include "fracture/fracture.hpp"
#include "fracture/mesh_repair.hpp"
#include "fracture/tests/broken_meshes.hpp"

using namespace dtlab;
using dtlab::test::box;
using dtlab::test::count_of;
using dtlab::test::join;

namespace {

void check_solid_pieces(const TriangleMesh& mesh, double volume, std::size_t pieces) {
  FractureOptions o;
  o.pieces = pieces;
  o.seed = 3;
  o.repair = true;
  const FractureResult r = fracture_mesh(mesh, o);
  CHECK(r.mesh_volume == Approx(volume).epsilon(1e-12));
  double sum = 0;
  for (const auto& p : r.pieces) sum += p.volume;
  CHECK(std::abs(sum - r.mesh_volume) <= 1e-9 * r.mesh_volume);
}

}  // namespace

TEST_CASE("repair: a duplicated vertex is merged") {
  TriangleMesh m = box({0, 0, 0}, {1, 1, 1});
  m.vertices.push_back(m.vertices[0]);  // vertex 8 = vertex 0
  for (auto& t : m.triangles)
    if (t[1] == 0) t[1] = 8;
  const MeshReport before = analyze_mesh(m);
  CHECK(before.duplicate_vertices == 1);
  CHECK(before.duplicate_at.size() == 1);
  CHECK(before.solid());  // the report judges the merged geometry
  const RepairResult r = repair_mesh(m);
  CHECK(count_of(r, "merged duplicate vertices") == 1);
  CHECK(r.solid());
  CHECK(r.mesh.vertices.size() == 8);
  CHECK(r.after.volume == Approx(1).epsilon(1e-14));
}

TEST_CASE("repair: a hole is filled") {
  TriangleMesh m = box({0, 0, 0}, {1, 1, 1});
  m.triangles.erase(m.triangles.begin() + 4, m.triangles.begin() + 6);  // one square side
  const MeshReport before = analyze_mesh(m);
  CHECK_FALSE(before.closed);
  CHECK(before.boundary_edges == 4);
  CHECK(before.boundary_loops == 1);
  CHECK(before.why_not_solid().find("not closed: 4 boundary edges in 1 boundary loop") == 0);
  const RepairResult r = repair_mesh(m);
  CHECK(count_of(r, "filled holes") == 1);
  REQUIRE(r.solid());
  CHECK(r.after.volume == Approx(1).epsilon(1e-14));
  check_solid_pieces(m, 1, 10);
}

TEST_CASE("repair: two overlapping boxes become their union") {
  const TriangleMesh m = join(box({0, 0, 0}, {1, 1, 1}), box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}));
  const MeshReport before = analyze_mesh(m);
  CHECK(before.closed);
  CHECK(before.self_intersections > 0);
  CHECK_FALSE(before.solid());
  CHECK(before.why_not_solid().find("self-intersecting") == 0);
  const RepairResult r = repair_mesh(m);
  CHECK(count_of(r, "resolved self-intersecting triangle pairs") == before.self_intersections);
  REQUIRE(r.solid());
  CHECK(r.after.volume == Approx(2 - 0.125).epsilon(1e-14));
  check_solid_pieces(m, 1.875, 12);
}

TEST_CASE("repair: degenerate triangles dropped, a flipped triangle and an inside-out shell oriented") {
  TriangleMesh m = box({0, 0, 0}, {1, 1, 1});
  m.vertices.push_back({0.5, 0, 0});
  m.triangles.push_back({0, 8, 1});  // collinear corners
  m.triangles.push_back({2, 2, 3});  // a repeated corner
  std::swap(m.triangles[0][1], m.triangles[0][2]);
  const MeshReport before = analyze_mesh(m);
  CHECK(before.degenerate_triangles == 2);
  CHECK(before.misoriented_edges == 3);
  CHECK_FALSE(before.oriented);
  const RepairResult r = repair_mesh(m);
  CHECK(count_of(r, "dropped degenerate triangles") == 2);
  CHECK(r.solid());
  CHECK(r.after.volume == Approx(1).epsilon(1e-14));

  TriangleMesh inside_out = box({0, 0, 0}, {2, 1, 1});
  for (auto& t : inside_out.triangles) std::swap(t[1], t[2]);
  CHECK(analyze_mesh(inside_out).volume < 0);
  const RepairResult o = repair_mesh(inside_out);
  CHECK(count_of(o, "reversed triangles to bound a volume") == 12);
  CHECK(o.after.volume == Approx(2).epsilon(1e-14));
}

TEST_CASE("repair: what encloses nothing is refused, naming what remains") {
  TriangleMesh tri;
  tri.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.triangles = {{0, 1, 2}};
  const RepairResult r = repair_mesh(tri);
  CHECK_FALSE(r.solid());
  CHECK_FALSE(r.after.why_not_solid().empty());
  FractureOptions o;
  o.repair = true;
  CHECK_THROWS_WITH(fracture_mesh(tri, o), Catch::Contains("cannot be repaired into a solid"));
  o.repair = false;
  CHECK_THROWS_WITH(fracture_mesh(tri, o), Catch::Contains("not a solid: not closed"));
}

TEST_CASE("report: a pinched vertex (a duplicated coordinate) is one diagnosis") {
  // Two tetrahedra touching at one point, the point written twice (as in cow.off).
  TriangleMesh a;
  a.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  a.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  TriangleMesh b = a;
  for (auto& p : b.vertices) p = Point3{-p.x, -p.y, -p.z};
  for (auto& t : b.triangles) std::swap(t[1], t[2]);
  const TriangleMesh m = join(a, b);
  const MeshReport r = analyze_mesh(m);
  CHECK(r.duplicate_vertices == 1);
  CHECK(r.nonmanifold_vertices == 1);
  CHECK_FALSE(r.manifold);
  CHECK(r.closed);
  CHECK(r.self_intersections == 0);
  FractureOptions o;
  CHECK_THROWS_WITH(fracture_mesh(m, o), Catch::Contains("not manifold: 0 edges in more than two triangles, 1 pinched vertex"));
}
