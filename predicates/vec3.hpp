#pragma once
// The one 3-vector arithmetic on Point3 (sampling, Voronoi cells, fracture): sums,
// scaling, dot and cross products, norms, componentwise min and max.
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
inline double det3(const Point3& a, const Point3& b, const Point3& c) { return dot(a, cross(b, c)); }

}  // namespace dtlab
