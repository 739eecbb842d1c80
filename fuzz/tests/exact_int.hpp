#pragma once
// Exact predicates for integer-valued points (|coordinate| < 2^22), in 128-bit
// integers: the tests' independent check that a claimed degeneracy really holds.
#include <cmath>
#include <cstdint>

#include "predicates/point.hpp"

namespace dtlab::fuzz::test {

using i128 = __int128;

inline bool is_small_int(double v) { return v == std::floor(v) && std::abs(v) < 0x1p22; }
inline bool is_small_int(const Point3& p) {
  return is_small_int(p.x) && is_small_int(p.y) && is_small_int(p.z);
}

struct I3 {
  i128 x, y, z;
};
inline I3 to_i3(const Point3& p) {
  return {static_cast<i128>(p.x), static_cast<i128>(p.y), static_cast<i128>(p.z)};
}
inline I3 sub(const I3& a, const I3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline I3 cross(const I3& a, const I3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline i128 dot(const I3& a, const I3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

inline int sign(i128 v) { return (v > 0) - (v < 0); }

// det[a-d; b-d; c-d]
inline int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const I3 D = to_i3(d);
  return sign(dot(sub(to_i3(a), D), cross(sub(to_i3(b), D), sub(to_i3(c), D))));
}

inline bool collinear(const Point3& a, const Point3& b, const Point3& c) {
  const I3 A = to_i3(a);
  const I3 n = cross(sub(to_i3(b), A), sub(to_i3(c), A));
  return n.x == 0 && n.y == 0 && n.z == 0;
}

// The lifted 4x4 determinant of (p - e, |p - e|^2) for p = a, b, c, d.
inline int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                    const Point3& e) {
  const I3 E = to_i3(e);
  const I3 r[4] = {sub(to_i3(a), E), sub(to_i3(b), E), sub(to_i3(c), E), sub(to_i3(d), E)};
  i128 det = 0;
  for (int skip = 0; skip < 4; ++skip) {
    I3 m[3];
    for (int i = 0, k = 0; i < 4; ++i)
      if (i != skip) m[k++] = r[i];
    const i128 minor = dot(m[0], cross(m[1], m[2]));
    const i128 lift = dot(r[skip], r[skip]);
    // Expansion along the lift column (the 4th): sign (-1)^(skip + 4 + 1)... with
    // rows ordered a, b, c, d the cofactor signs alternate -, +, -, +.
    det += (skip % 2 == 0 ? -1 : 1) * lift * minor;
  }
  return sign(det);
}

// 2D incircle of the projections dropping coordinate `axis`.
inline int incircle2d(const Point3& a, const Point3& b, const Point3& c, const Point3& d, int axis) {
  const auto proj = [axis](const Point3& p) -> std::pair<i128, i128> {
    if (axis == 0) return {static_cast<i128>(p.y), static_cast<i128>(p.z)};
    if (axis == 1) return {static_cast<i128>(p.z), static_cast<i128>(p.x)};
    return {static_cast<i128>(p.x), static_cast<i128>(p.y)};
  };
  const auto [dx, dy] = proj(d);
  i128 m[3][3];
  const Point3* ps[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    const auto [x, y] = proj(*ps[i]);
    m[i][0] = x - dx;
    m[i][1] = y - dy;
    m[i][2] = m[i][0] * m[i][0] + m[i][1] * m[i][1];
  }
  return sign(m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
              m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
              m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]));
}

inline bool collinear2d(const Point3& a, const Point3& b, const Point3& c, int axis) {
  const I3 n = cross(sub(to_i3(b), to_i3(a)), sub(to_i3(c), to_i3(a)));
  return (axis == 0 ? n.x : axis == 1 ? n.y : n.z) == 0;
}

}  // namespace dtlab::fuzz::test
