#include <catch2/catch.hpp>

#include "sampling/bumpy_torus.hpp"
#include "sampling/mesh_report.hpp"

using namespace dtlab;

TEST_CASE("bumpy torus is closed, manifold, outward oriented and embedded") {
  const TriangleMesh m = make_bumpy_torus();
  const MeshReport r = analyze_mesh(m);
  CHECK(r.closed);
  CHECK(r.manifold);
  CHECK(r.oriented);
  CHECK(r.degenerate_triangles == 0);
  CHECK(r.self_intersections == 0);
  // Euler characteristic of a torus: V - E + F = 0 with E = 3F/2.
  CHECK(static_cast<long>(r.vertices) - static_cast<long>(3 * r.triangles / 2) + static_cast<long>(r.triangles) == 0);
}

TEST_CASE("bumpy torus volume converges to the analytic value as the grid is refined") {
  BumpyTorusParams p;
  const double exact = bumpy_torus_volume(p);
  const double coarse = signed_volume(make_bumpy_torus(p));
  CHECK(coarse > 0);  // outward orientation
  CHECK(coarse == Approx(exact).epsilon(0.01));
  p.nu *= 2;
  p.nv *= 2;
  const double fine = signed_volume(make_bumpy_torus(p));
  CHECK(std::abs(fine - exact) < std::abs(coarse - exact));
}

TEST_CASE("bumpy torus rejects parameters that would self-intersect") {
  BumpyTorusParams p;
  p.minor = 0.9;
  CHECK_THROWS_AS(make_bumpy_torus(p), std::invalid_argument);
}
