#pragma once
// An axis-aligned box that grows by the points and boxes added to it (the BVH, the
// samplers).
#include <algorithm>
#include <cmath>

#include "predicates/vec3.hpp"

namespace dtlab {

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
    return lo.x <= b.hi.x && b.lo.x <= hi.x && lo.y <= b.hi.y && b.lo.y <= hi.y && lo.z <= b.hi.z && b.lo.z <= hi.z;
  }
};

}  // namespace dtlab
