#pragma once
// Small vector arithmetic on Point3, used as a 3-vector by the sampling code.
#include <algorithm>
#include <cmath>

#include "predicates/point.hpp"

namespace dtlab {

inline Point3 operator+(const Point3& a, const Point3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Point3 operator-(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Point3 operator*(double s, const Point3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Point3& operator+=(Point3& a, const Point3& b) {
  a.x += b.x;
  a.y += b.y;
  a.z += b.z;
  return a;
}
inline double dot(const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Point3 cross(const Point3& a, const Point3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm2(const Point3& a) { return dot(a, a); }
inline double norm(const Point3& a) { return std::sqrt(dot(a, a)); }
inline double coord(const Point3& a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }
inline Point3 min3(const Point3& a, const Point3& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
inline Point3 max3(const Point3& a, const Point3& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}

// Axis-aligned box; empty() until the first point is added.
struct Box3 {
  Point3 lo{INFINITY, INFINITY, INFINITY};
  Point3 hi{-INFINITY, -INFINITY, -INFINITY};
  void add(const Point3& p) {
    lo = min3(lo, p);
    hi = max3(hi, p);
  }
  void add(const Box3& b) {
    lo = min3(lo, b.lo);
    hi = max3(hi, b.hi);
  }
  bool empty() const { return lo.x > hi.x; }
  Point3 extent() const { return hi - lo; }
  Point3 center() const { return 0.5 * (lo + hi); }
  double volume() const {
    const Point3 e = extent();
    return empty() ? 0.0 : e.x * e.y * e.z;
  }
  double half_area() const {
    const Point3 e = extent();
    return empty() ? 0.0 : e.x * e.y + e.y * e.z + e.z * e.x;
  }
  int longest_axis() const {
    const Point3 e = extent();
    return e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
  }
  // Squared distance from p to the box (0 inside).
  double distance2(const Point3& p) const {
    const double dx = std::max({lo.x - p.x, 0.0, p.x - hi.x});
    const double dy = std::max({lo.y - p.y, 0.0, p.y - hi.y});
    const double dz = std::max({lo.z - p.z, 0.0, p.z - hi.z});
    return dx * dx + dy * dy + dz * dz;
  }
  bool overlaps(const Box3& b) const {
    return lo.x <= b.hi.x && b.lo.x <= hi.x && lo.y <= b.hi.y && b.lo.y <= hi.y &&
           lo.z <= b.hi.z && b.lo.z <= hi.z;
  }
};

}  // namespace dtlab
