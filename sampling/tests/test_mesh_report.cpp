#include <catch2/catch.hpp>

#include "predicates/naive.hpp"
#include "sampling/bumpy_torus.hpp"
#include "sampling/mesh_report.hpp"
#include "sampling/self_intersection.hpp"

using namespace dtlab;

namespace {
TriangleMesh tetrahedron() {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}
}  // namespace

TEST_CASE("report: open, flipped and non-manifold meshes are told apart") {
  TriangleMesh m = tetrahedron();
  CHECK(analyze_mesh(m).closed);
  m.triangles.pop_back();
  MeshReport open = analyze_mesh(m);
  CHECK_FALSE(open.closed);
  CHECK(open.manifold);
  CHECK(open.oriented);
  CHECK(open.boundary_edges == 3);

  m = tetrahedron();
  std::swap(m.triangles[3][0], m.triangles[3][1]);
  MeshReport flipped = analyze_mesh(m);
  CHECK(flipped.closed);
  CHECK_FALSE(flipped.oriented);
  CHECK(flipped.misoriented_edges == 3);

  m = tetrahedron();
  m.vertices.push_back({-1, -1, 0.5});
  m.triangles.push_back({0, 1, 4});  // a fin on edge 0-1: three triangles there
  MeshReport fin = analyze_mesh(m);
  CHECK_FALSE(fin.manifold);
  CHECK_FALSE(fin.closed);
  CHECK(fin.nonmanifold_edges == 1);
}

TEST_CASE("self-intersections: crossing, touching and shared-feature pairs") {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0},             // 0: in z = 0
                {0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0.5},  // 1: pierces 0
                {5, 5, 5}, {6, 5, 5}, {5, 6, 5},             // 2: far away
                {1, 0, 0}, {0, 0, 1}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  const NaivePredicates P;
  CHECK(triangles_intersect(m, 0, 1, P));
  CHECK_FALSE(triangles_intersect(m, 0, 2, P));
  // Sharing an edge at a fold angle: not an intersection.
  m.triangles.push_back({0, 1, 10});
  CHECK_FALSE(triangles_intersect(m, 0, 3, P));
  // Coplanar and folded back over the shared edge: an intersection.
  m.vertices.push_back({1, 1, 0});
  m.triangles.push_back({0, 1, 11});
  CHECK(triangles_intersect(m, 0, 4, P));
  // Sharing a vertex only, the other triangle crossing through: an intersection.
  m.vertices.push_back({0.5, 0.5, -1});
  m.vertices.push_back({0.5, 0.5, 1});
  m.triangles.push_back({0, 12, 13});
  CHECK(triangles_intersect(m, 0, 5, P));

  const Bvh bvh(m);
  std::uint64_t brute = 0;
  for (std::uint32_t s = 0; s < m.triangles.size(); ++s)
    for (std::uint32_t t = s + 1; t < m.triangles.size(); ++t) brute += triangles_intersect(m, s, t, P);
  CHECK(count_self_intersections(bvh, P) == brute);
}

TEST_CASE("self-intersections: two interpenetrating tori are found, one torus is clean") {
  TriangleMesh a = make_bumpy_torus({.nu = 32, .nv = 16});
  CHECK(analyze_mesh(a).self_intersections == 0);
  TriangleMesh b = a;
  const auto n = static_cast<std::uint32_t>(a.vertices.size());
  for (Point3 p : b.vertices) a.vertices.push_back({p.x + 0.7, p.y, p.z + 0.1});
  for (auto t : b.triangles) a.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  CHECK(analyze_mesh(a).self_intersections > 0);
}

TEST_CASE("report: holes, duplicates and degenerate triangles with locations") {
  // A tetrahedron with two faces removed: one boundary loop of four edges; two
  // separate triangles: two loops.
  TriangleMesh m = tetrahedron();
  m.triangles.resize(2);
  MeshReport r = analyze_mesh(m);
  CHECK(r.boundary_edges == 4);
  CHECK(r.boundary_loops == 1);
  CHECK(r.boundary_at.size() == 3);
  CHECK_FALSE(r.solid());
  CHECK(r.why_not_solid().find("not closed: 4 boundary edges in 1 boundary loop, e.g. at (") == 0);

  TriangleMesh two;
  two.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
  two.triangles = {{0, 1, 2}, {3, 4, 5}};
  CHECK(analyze_mesh(two).boundary_loops == 2);

  // Collinear corners, decided exactly: a corner 1e-15 off the line is not collinear.
  TriangleMesh d;
  d.vertices = {{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {1, 1, 1 + 1e-15}};
  d.triangles = {{0, 1, 2}, {0, 3, 2}};
  r = analyze_mesh(d);
  CHECK(r.degenerate_triangles == 1);
  CHECK(r.degenerate_at.size() == 1);

  TriangleMesh dup = tetrahedron();
  dup.vertices.push_back(dup.vertices[3]);
  dup.triangles[3] = {1, 2, 4};
  r = analyze_mesh(dup);
  CHECK(r.duplicate_vertices == 1);
  CHECK(r.solid());
  CHECK(r.volume == Approx(1.0 / 6));
  CHECK(r.summary().find("closed, manifold, oriented, 0 self-intersecting pairs") != std::string::npos);
}

TEST_CASE("report: magnitudes a double cannot measure, above and below", "[magnitude]") {
  const auto scaled = [](double s) {
    TriangleMesh m = tetrahedron();
    for (Point3& p : m.vertices) p = s * p;
    return m;
  };
  // Side 1e80: area 1e160 and volume 1e239 are doubles (the area's squares are not).
  CHECK(analyze_mesh(scaled(1e80)).solid());
  CHECK(analyze_mesh(scaled(1e-100)).solid());
  for (double s : {1e-110, 1e-160, 1e-300}) {
    INFO("side " << s);
    const MeshReport r = analyze_mesh(scaled(s));
    CHECK_FALSE(r.solid());
    CHECK(r.magnitude.volume_underflow);
    CHECK(r.why_not_solid().find("coordinates too small") != std::string::npos);
    CHECK(r.why_not_solid().find("encloses no volume") == std::string::npos);
  }
  CHECK(analyze_mesh(scaled(1e103)).magnitude.overflow);
  // A closed mesh that is flat at a normal scale still encloses no volume.
  TriangleMesh flat = tetrahedron();
  flat.vertices[3] = {0.25, 0.25, 0};
  const MeshReport f = analyze_mesh(flat);
  CHECK_FALSE(f.magnitude.volume_underflow);
  CHECK_FALSE(f.solid());
  // Surface points need the area only: an open triangle of side 1e-90 has one (1e-180).
  TriangleMesh tri = scaled(1e-90);
  tri.triangles.resize(1);
  CHECK(magnitude_problem(measure_magnitude(tri, surface_area(tri), signed_volume(tri)), true).empty());
}
