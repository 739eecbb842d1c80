// The semi-static filters' error bounds (adaptive.hpp), measured: on the hard
// families the naive determinant's error, against a quad-precision reference, must
// stay below the derived bound (before its slack). Also prints the largest ratio seen,
// which shows how far the worst case of the derivation is from typical inputs.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "families.hpp"
#include "predicates/error_bounds.hpp"
#include "predicates/naive.hpp"

using namespace dtlab;
using namespace dtlab::test;

namespace {

using Quad128 = __float128;  // 113-bit mantissa: the differences here are exact in it

Quad128 abs128(Quad128 v) { return v < 0 ? -v : v; }

Quad128 insphere128(const Quint& q) {
  Quad128 m[4][4];
  for (int i = 0; i < 4; ++i) {
    const Quad128 x = Quad128(q[i].x) - q[4].x, y = Quad128(q[i].y) - q[4].y,
                  z = Quad128(q[i].z) - q[4].z;
    m[i][0] = x, m[i][1] = y, m[i][2] = z, m[i][3] = x * x + y * y + z * z;
  }
  auto det3 = [&](int r0, int r1, int r2) {
    return m[r0][0] * (m[r1][1] * m[r2][2] - m[r1][2] * m[r2][1]) -
           m[r0][1] * (m[r1][0] * m[r2][2] - m[r1][2] * m[r2][0]) +
           m[r0][2] * (m[r1][0] * m[r2][1] - m[r1][1] * m[r2][0]);
  };
  // Expansion along the lift column, signs as in naive.hpp.
  return m[3][3] * det3(0, 1, 2) - m[2][3] * det3(3, 0, 1) + m[1][3] * det3(2, 3, 0) -
         m[0][3] * det3(1, 2, 3);
}

Quad128 orient128(const Quad& q) {
  Quad128 m[3][3];
  for (int i = 0; i < 3; ++i)
    m[i][0] = Quad128(q[i].x) - q[3].x, m[i][1] = Quad128(q[i].y) - q[3].y,
    m[i][2] = Quad128(q[i].z) - q[3].z;
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

constexpr double kEps = error_bounds::kEps;

}  // namespace

TEST_CASE("semi-static insphere error stays below 311.78 eps L^2.5", "[adaptive][semistatic]") {
  double worst = 0;
  int measured = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed)
    for (const Quint& q : hard_insphere_inputs(seed, 300)) {
      const double det = insphere_value(q[0], q[1], q[2], q[3], q[4]);
      double lift = 0;
      for (int i = 0; i < 4; ++i) {
        const double x = q[i].x - q[4].x, y = q[i].y - q[4].y, z = q[i].z - q[4].z;
        lift = std::max(lift, x * x + y * y + z * z);
      }
      // Natural scales only: quad precision is exact enough and nothing underflows.
      if (!(lift >= 0x1p-100 && lift <= 0x1p100)) continue;
      const Quad128 scale = Quad128(kEps) * lift * lift * Quad128(std::sqrt(lift));
      const double ratio = double(abs128(Quad128(det) - insphere128(q)) / scale);
      worst = std::max(worst, ratio);
      ++measured;
      REQUIRE(ratio <= 311.78);
    }
  std::printf("semi-static insphere: largest |error| / (eps L^2.5) = %.3f over %d inputs (bound 320)\n",
              worst, measured);
  CHECK(measured > 1000);
}

TEST_CASE("semi-static orient3d error stays below 42 eps mx my mz", "[adaptive][semistatic]") {
  double worst = 0;
  int measured = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed)
    for (const Quad& q : hard_orient_inputs(seed, 300)) {
      double m[3] = {0, 0, 0};
      for (int i = 0; i < 3; ++i) {
        m[0] = std::max(m[0], std::fabs(q[i].x - q[3].x));
        m[1] = std::max(m[1], std::fabs(q[i].y - q[3].y));
        m[2] = std::max(m[2], std::fabs(q[i].z - q[3].z));
      }
      const double p = m[0] * m[1] * m[2];
      if (!(p >= 0x1p-300 && p <= 0x1p300)) continue;
      const double det = orient3d_value(q[0], q[1], q[2], q[3]);
      const double ratio = double(abs128(Quad128(det) - orient128(q)) / (Quad128(kEps) * p));
      worst = std::max(worst, ratio);
      ++measured;
      REQUIRE(ratio <= 42.0);
    }
  std::printf("semi-static orient3d: largest |error| / (eps mx my mz) = %.3f over %d inputs (bound 43)\n",
              worst, measured);
  CHECK(measured > 1000);
}
