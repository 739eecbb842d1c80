// The checker's filtered predicates agree with GMP, including on mixed huge and
// subnormal coordinates, where an underflowing product once broke the filter.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "oracle/check/filtered_exact.hpp"
#include "predicates/exact.hpp"

using namespace dtlab;

TEST_CASE("filtered exact equals exact on mixed magnitudes", "[check]") {
  FilteredExact f;
  ExactPredicates ex;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> expo(-1070, 1000);
  int checked = 0;
  for (int i = 0; i < 20000; ++i) {
    Point3 p[5];
    for (auto& q : p) q = {std::ldexp(u(rng), expo(rng)), std::ldexp(u(rng), expo(rng)), std::ldexp(u(rng), expo(rng))};
    REQUIRE(f.orient3d(p[0], p[1], p[2], p[3]) == ex.orient3d(p[0], p[1], p[2], p[3]));
    REQUIRE(f.insphere(p[0], p[1], p[2], p[3], p[4]) == ex.insphere(p[0], p[1], p[2], p[3], p[4]));
    ++checked;
  }
  // The shrunk libFuzzer find: one point at -1.157e294, three near 1e-317.
  const Point3 big{-1.157e294, -1.157e294, -1.157e294};
  const Point3 s1{1e-317, 2e-317, 0}, s2{3e-317, -1e-317, 5e-318}, s3{-2e-317, 4e-317, 1e-317};
  CHECK(f.orient3d(big, s1, s2, s3) == ex.orient3d(big, s1, s2, s3));
  CHECK(f.orient3d(s3, s1, s2, big) == ex.orient3d(s3, s1, s2, big));
  CHECK(checked == 20000);
}

// A case built so that only the safe-range test stands between the filter and a wrong
// sign (disabling it fails this test). With d at the origin, a = (1, 0, 2^600),
// b = (1.25 2^-537, 2^-537, 2^57), c = (2^-537, 2^-537, 0):
//   det = adz (bdx cdy - cdx bdy) - bdz adx cdy = 2^600 (0.25 2^-1074) - 2^57 2^-537
//       = 2^-476 - 2^-480 > 0,
// but bdx cdy = 1.25 2^-1074 rounds to the subnormal 2^-1074, equal to cdx bdy, so the
// doubles give det = -2^-480, far above the stage-A bound times the permanent (~2^-523):
// Shewchuk's bound assumes no product underflows, and 2^-537 is below kSafeLow.
TEST_CASE("filtered exact: an underflowing product inside a trusted-looking determinant", "[check]") {
  const Point3 a{1, 0, 0x1p600}, b{0x1.4p-537, 0x1p-537, 0x1p57}, c{0x1p-537, 0x1p-537, 0}, d{0, 0, 0};
  ExactPredicates ex;
  REQUIRE(ex.orient3d(a, b, c, d) == 1);
  // The doubles' determinant has the other sign: what the filter alone would return.
  const double adx = a.x, adz = a.z, bdx = b.x, bdy = b.y, bdz = b.z, cdx = c.x, cdy = c.y;
  REQUIRE(adz * (bdx * cdy - cdx * bdy) - bdz * (adx * cdy) < 0);
  FilteredExact f;
  CHECK(f.orient3d(a, b, c, d) == 1);
}
