#include <catch2/catch.hpp>

#include <string>

#include "fracture/fracture.hpp"
#include "fracture/mesh_repair.hpp"
#include "fracture/pinched_vertices.hpp"
#include "fracture/tests/broken_meshes.hpp"
#include "fracture/winding_solid.hpp"
#include "sampling/winding_number.hpp"

using namespace dtlab;
using dtlab::test::box;
using dtlab::test::count_of;
using dtlab::test::join;

namespace {

TriangleMesh reversed(TriangleMesh m) {
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

// The volume where the winding number of `m` is >= 1/2, counted on an n^3 grid of cell
// centres over its box (brute-force winding numbers: independent of the code under test).
double grid_volume(const TriangleMesh& m, int n) {
  const Box3 b = bounding_box(m);
  const Point3 d = b.hi - b.lo;
  std::size_t inside = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Point3 q{b.lo.x + (i + 0.5) * d.x / n, b.lo.y + (j + 0.5) * d.y / n, b.lo.z + (k + 0.5) * d.z / n};
        inside += winding_number_exact(m, q) >= 0.5;
      }
  return d.x * d.y * d.z * static_cast<double>(inside) / (static_cast<double>(n) * n * n);
}

// A unit cube whose corner (1, 1, 1) is pushed through the bottom: one closed shell that
// crosses itself.
TriangleMesh pushed_corner_cube() {
  TriangleMesh m = box({0, 0, 0}, {1, 1, 1});
  m.vertices[7] = {0.7, 0.6, -0.4};
  return m;
}

}  // namespace

TEST_CASE("winding solid: overlapping boxes, a reversed box, a box inside a box") {
  const TriangleMesh a = box({0, 0, 0}, {1, 1, 1}), b = box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5});
  WindingSolid u = winding_number_solid(join(a, b), 10);
  REQUIRE(u.ok);
  MeshReport r = analyze_mesh(u.mesh);
  CHECK(r.solid());
  CHECK(r.volume == Approx(1.875).epsilon(1e-14));  // the union

  WindingSolid d = winding_number_solid(join(a, reversed(b)), 10);
  REQUIRE(d.ok);
  r = analyze_mesh(d.mesh);
  CHECK(r.solid());
  CHECK(r.volume == Approx(0.875).epsilon(1e-14));  // a minus b: w = 1 - 1 = 0 in the overlap
  CHECK(d.kept == d.patches - 2);  // only b's faces outside a and a's faces inside b go

  WindingSolid n = winding_number_solid(join(box({0, 0, 0}, {2, 2, 2}), b), 10);  // w = 2 inside b
  REQUIRE(n.ok);
  CHECK(n.patches == 2);
  CHECK(n.kept == 1);
  r = analyze_mesh(n.mesh);
  CHECK(r.solid());
  CHECK(r.volume == Approx(8).epsilon(1e-14));
}

TEST_CASE("winding solid: one shell crossing itself, against a grid count of the winding number") {
  const TriangleMesh m = pushed_corner_cube();
  const MeshReport before = analyze_mesh(m);
  CHECK(before.closed);
  CHECK(before.self_intersections > 0);
  const WindingSolid w = winding_number_solid(m, 10);
  REQUIRE(w.ok);
  CHECK(w.patches > 1);
  const MeshReport r = analyze_mesh(w.mesh);
  CHECK(r.solid());
  const double grid = grid_volume(m, 60);
  CHECK(r.volume == Approx(grid).epsilon(0.02));

  const RepairResult repaired = repair_mesh(m);
  REQUIRE(repaired.solid());
  CHECK(count_of(repaired, "resolved self-intersecting triangle pairs") == before.self_intersections);
  CHECK(repaired.after.volume == Approx(grid).epsilon(0.02));
}

TEST_CASE("pinched vertices: two tetrahedra touching at a point are separated") {
  TriangleMesh a;
  a.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  a.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  TriangleMesh b = a;
  for (auto& p : b.vertices) p = Point3{-p.x, -p.y, -p.z};
  const TriangleMesh m = join(a, reversed(b));
  CHECK(analyze_mesh(m).nonmanifold_vertices == 1);

  TriangleMesh s = m;
  CHECK(separate_pinched_vertices(s) == 1);
  CHECK(s.vertices.size() == 8);
  const MeshReport r = analyze_mesh(s);
  CHECK(r.solid());
  CHECK(r.volume == Approx(2.0 / 6).epsilon(2e-3));  // each apex moved 1e-3 of the way in
  TriangleMesh again = s;
  CHECK(separate_pinched_vertices(again) == 0);

  const RepairResult repaired = repair_mesh(m);
  REQUIRE(repaired.solid());
  CHECK(count_of(repaired, "separated pinched vertices") == 1);
  FractureOptions o;
  o.pieces = 8;
  o.seed = 3;
  o.repair = true;
  const FractureResult f = fracture_mesh(m, o);
  double sum = 0;
  for (const auto& p : f.pieces) sum += p.volume;
  CHECK(std::abs(sum - f.mesh_volume) <= 1e-9 * f.mesh_volume);
}
