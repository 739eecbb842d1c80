#pragma once
// A point of R^3 in double precision: the only geometric input type of dtlab.
#include <cmath>
#include <compare>

namespace dtlab {

struct Point3 {
  double x, y, z;
  friend bool operator==(const Point3&, const Point3&) = default;
};

// Every coordinate finite: no predicate has a sign for a NaN or an infinity.
inline bool is_finite(const Point3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Lexicographic order on (x, y, z): the order the symbolic perturbation uses.
inline bool lex_less(const Point3& a, const Point3& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

}  // namespace dtlab
