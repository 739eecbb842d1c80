#pragma once
// Small inputs for the oracle tests: uniform, lattice (many cospherical and
// coplanar points), integer points on one sphere (exactly cospherical).
#include <vector>

#include "predicates/point.hpp"
#include "tests/support/random_points.hpp"

namespace dtlab::test {

// In the unit cube (tests/support/random_points.hpp).
inline std::vector<Point3> uniform_points(int n, unsigned seed) {
  return uniform(static_cast<std::size_t>(n), seed, 0.0, 1.0);
}

inline std::vector<Point3> lattice_points(int m) {
  std::vector<Point3> p;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k) p.push_back({0.5 * i, 0.5 * j, 0.5 * k});
  return p;
}

// All integer points with x^2 + y^2 + z^2 == r2.
inline std::vector<Point3> sphere_points(int r2) {
  std::vector<Point3> p;
  int r = 0;
  while ((r + 1) * (r + 1) <= r2) ++r;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      for (int z = -r; z <= r; ++z)
        if (x * x + y * y + z * z == r2) p.push_back({double(x), double(y), double(z)});
  return p;
}

}  // namespace dtlab::test
