#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "predicates/exact.hpp"
#include "predicates/naive.hpp"

using dtlab::ExactPredicates;
using dtlab::Point3;

namespace {
const Point3 kA{0, 0, 0}, kB{1, 0, 0}, kC{0, 1, 0}, kD{0, 0, -1};
}

TEST_CASE("exact: sign convention of orient3d and insphere", "[exact]") {
  const ExactPredicates ex;
  // a,b,c counter-clockwise seen from +z, d below: positive.
  CHECK(ex.orient3d(kA, kB, kC, kD) == 1);
  CHECK(ex.orient3d(kA, kB, kC, Point3{0, 0, 1}) == -1);
  CHECK(ex.orient3d(kA, kB, kC, Point3{0.3, 0.7, 0}) == 0);
  CHECK(ex.insphere(kA, kB, kC, kD, Point3{0.25, 0.25, -0.25}) == 1);
  CHECK(ex.insphere(kA, kB, kC, kD, Point3{3, 3, 3}) == -1);
  CHECK(ex.insphere(kA, kB, kC, kD, Point3{1, 1, 0}) == 0);  // on the sphere
  // Orientation flips the insphere sign.
  CHECK(ex.insphere(kB, kA, kC, kD, Point3{0.25, 0.25, -0.25}) == -1);
}

TEST_CASE("exact: scale invariance across the whole double range", "[exact]") {
  const ExactPredicates ex;
  const Point3 e{1, 1, 0};  // cospherical
  const Point3 in{0.25, 0.25, -0.25};
  for (int k : {-1074 + 3, -1060, -1022, -600, -140, 0, 140, 500, 1020}) {
    auto s = [k](const Point3& p) {
      return Point3{std::ldexp(p.x, k), std::ldexp(p.y, k), std::ldexp(p.z, k)};
    };
    INFO("scale 2^" << k);
    CHECK(ex.orient3d(s(kA), s(kB), s(kC), s(kD)) == 1);
    CHECK(ex.insphere(s(kA), s(kB), s(kC), s(kD), s(e)) == 0);
    CHECK(ex.insphere(s(kA), s(kB), s(kC), s(kD), s(in)) == 1);
  }
}

TEST_CASE("exact: one ulp off a plane is seen", "[exact]") {
  const ExactPredicates ex;
  const double tiny = std::numeric_limits<double>::denorm_min();
  CHECK(ex.orient3d(kA, kB, kC, Point3{0.5, 0.5, -tiny}) == 1);
  CHECK(ex.orient3d(kA, kB, kC, Point3{0.5, 0.5, tiny}) == -1);
  // Huge triangle, point a denormal below its plane.
  CHECK(ex.orient3d(kA, Point3{1e300, 0, 0}, Point3{0, 1e300, 0}, Point3{0.5, 0.5, -tiny}) == 1);
  // (1 + 2^-52, 0, -2^-52) lies on the plane x + y + z = 1; a denormal step leaves it.
  const double up = std::nextafter(1.0, 2.0), ulp = up - 1.0;
  const Point3 p{1, 0, 0}, q{0, 1, 0}, r{0, 0, 1};
  CHECK(ex.orient3d(p, q, r, Point3{up, 0, -ulp}) == 0);
  CHECK(ex.orient3d(p, q, r, Point3{up, tiny, -ulp}) == -1);
  CHECK(ex.orient3d(p, q, r, Point3{up, -tiny, -ulp}) == 1);
}
