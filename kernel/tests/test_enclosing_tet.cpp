// --boundary bigtet: the enclosing tetrahedron is proven or the build names the failure;
// non-finite input and factors are refused.
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

#include "kernel/build.hpp"
#include "kernel/enclosing_tet.hpp"
#include "kernel/spatial_order.hpp"
#include "predicates/exact.hpp"

using namespace dtlab;

namespace {
const std::vector<Point3> kFive = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
const PredicateSpec kAdaptive{"adaptive", 1e-12, false, true};
BuildOptions bigtet(double factor) {
  BuildOptions o;
  o.boundary = Boundary::bigtet;
  o.bigtet_factor = factor;
  return o;
}
}  // namespace

TEST_CASE("enclosing tet: valid around ordinary points, proven with exact predicates") {
  const EnclosingTet t = enclosing_tet(kFive, 1.5);
  REQUIRE(t.valid());
  // FACTOR 1 touches the box's low corner, here an input point: not strictly inside.
  CHECK_FALSE(enclosing_tet(kFive, 1).valid());
  const ExactPredicates e;
  CHECK(e.orient3d(t.corners[0], t.corners[1], t.corners[2], t.corners[3]) > 0);
  const BuildResult r = build_delaunay(kFive, kAdaptive, bigtet(10));
  CHECK_FALSE(r.failure);
  CHECK_FALSE(r.mesh.tets.empty());
}

TEST_CASE("enclosing tet: corners that overflow are a named failure, not 0 tets") {
  const std::vector<Point3> e307 = {{1e307, 0, 0}, {-1e307, 0, 0}, {0, 1e307, 0}, {0, 0, 1e307}, {1, 2, 3}};
  CHECK(enclosing_tet(e307, 1).valid());  // r = 3e307 still fits a double
  CHECK_FALSE(enclosing_tet(e307, 10).valid());
  const BuildResult r = build_delaunay(e307, kAdaptive, bigtet(10));
  REQUIRE(r.failure);
  CHECK(r.failure->kind == FailureKind::outside_boundary);
  CHECK(r.skipped.size() == e307.size());
  // The infinite boundary has no such limit.
  CHECK_FALSE(build_delaunay(e307, kAdaptive).failure);
}

TEST_CASE("enclosing tet: FACTOR below 1 is tested point by point") {
  // Points on a sphere fit in a tet smaller than the one around their box.
  const std::vector<Point3> pts = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const EnclosingTet t = enclosing_tet(pts, 0.9);
  CHECK(t.valid());
  CHECK_FALSE(enclosing_tet(pts, 0.3).valid());
}

TEST_CASE("bad FACTOR and non-finite coordinates are refused by the library") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double f : {0.0, -1.0, nan, inf}) {
    CHECK_THROWS_AS(enclosing_tet(kFive, f), std::invalid_argument);
    CHECK_THROWS_AS(build_delaunay(kFive, kAdaptive, bigtet(f)), std::invalid_argument);
  }
  for (Point3 bad : {Point3{nan, 0, 0}, Point3{0, inf, 0}, Point3{0, 0, -inf}}) {
    std::vector<Point3> pts = kFive;
    pts.push_back(bad);
    for (const char* backend : {"naive", "epsilon", "adaptive", "exact"})
      CHECK_THROWS_AS(build_delaunay(pts, PredicateSpec{backend, 1e-12, false, true}), std::invalid_argument);
  }
}

TEST_CASE("coplanar and collinear input is lower-dimensional with bigtet too") {
  const std::vector<Point3> flat = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.25, 0}};
  const std::vector<Point3> line = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  for (const auto& pts : {flat, line}) {
    const BuildResult r = build_delaunay(pts, kAdaptive, bigtet(10));
    REQUIRE(r.failure);
    CHECK(r.failure->kind == FailureKind::lower_dimensional);
  }
}

TEST_CASE("BRIO order on an axis extent below 5.7e-306 (0 * inf would be NaN)") {
  // cli_subnormal_axis.xyz: z spans 1e-310; its Hilbert scale is infinite.
  const std::vector<Point3> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1e-310}, {1, 1, 1e-310}};
  std::vector<std::uint32_t> order = brio_order(pts, 1);
  std::sort(order.begin(), order.end());
  CHECK(order == std::vector<std::uint32_t>{0, 1, 2, 3, 4});
}
