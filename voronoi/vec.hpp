#pragma once
// 3-vector arithmetic on Point3 and an axis-aligned box, for the Voronoi code.
#include <algorithm>
#include <cmath>

#include "predicates/point.hpp"

namespace dtlab::vor {

inline Point3 vadd(const Point3& a, const Point3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Point3 vsub(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Point3 vscale(double s, const Point3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline double vdot(const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Point3 vcross(const Point3& a, const Point3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double vnorm(const Point3& a) { return std::sqrt(vdot(a, a)); }
inline double det3(const Point3& a, const Point3& b, const Point3& c) { return vdot(a, vcross(b, c)); }

struct Box {
  Point3 lo{0, 0, 0}, hi{0, 0, 0};
  double volume() const { return (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z); }
  double diagonal() const { return vnorm(vsub(hi, lo)); }
  bool contains(const Point3& p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
};

}  // namespace dtlab::vor
