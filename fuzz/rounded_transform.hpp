#pragma once
// A similarity transform evaluated in rounded double arithmetic: it moves an
// exact configuration to a nearby one where the degeneracy holds only up to
// rounding, the hardest inputs for floating-point predicates.
//
// The rotation comes from an integer quaternion q = (a, b, c, d): with
// n = a^2 + b^2 + c^2 + d^2, R = M / n where M has integer entries such as
// a^2 + b^2 - c^2 - d^2 and 2(bc - ad). R is an exact rational rotation; only the
// division by n and the products with the points round. No sin/cos is used, so
// the result is the same on every IEEE-754 machine.
#include <array>
#include <cstdint>

#include "fuzz/rng.hpp"
#include "predicates/point.hpp"

namespace dtlab::fuzz {

struct RoundedTransform {
  std::array<double, 9> rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major, rounded
  double scale = 1;
  Point3 translation{0, 0, 0};

  Point3 apply(const Point3& p) const {
    const auto& r = rotation;
    const double x = r[0] * p.x + r[1] * p.y + r[2] * p.z;
    const double y = r[3] * p.x + r[4] * p.y + r[5] * p.z;
    const double z = r[6] * p.x + r[7] * p.y + r[8] * p.z;
    return {scale * x + translation.x, scale * y + translation.y, scale * z + translation.z};
  }
};

inline std::array<double, 9> rational_rotation(std::int64_t a, std::int64_t b, std::int64_t c,
                                               std::int64_t d) {
  const auto n = static_cast<double>(a * a + b * b + c * c + d * d);
  const auto e = [n](std::int64_t v) { return static_cast<double>(v) / n; };
  return {e(a * a + b * b - c * c - d * d), e(2 * (b * c - a * d)),     e(2 * (b * d + a * c)),
          e(2 * (b * c + a * d)),     e(a * a - b * b + c * c - d * d), e(2 * (c * d - a * b)),
          e(2 * (b * d - a * c)),     e(2 * (c * d + a * b)),     e(a * a - b * b - c * c + d * d)};
}

// A random transform: quaternion entries in [-20, 20] (not all zero), scale in
// [0.5, 2), translation in [-1000, 1000)^3.
inline RoundedTransform random_transform(Rng& rng) {
  RoundedTransform t;
  std::int64_t q[4];
  do {
    for (auto& v : q) v = rng.range(-20, 20);
  } while (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0);
  t.rotation = rational_rotation(q[0], q[1], q[2], q[3]);
  t.scale = rng.uniform(0.5, 2.0);
  t.translation = {rng.uniform(-1000, 1000), rng.uniform(-1000, 1000), rng.uniform(-1000, 1000)};
  return t;
}

}  // namespace dtlab::fuzz
