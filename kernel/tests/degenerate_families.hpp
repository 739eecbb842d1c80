#pragma once
// Point sets built to hit every degenerate case of the flips (test_degenerate.cpp,
// test_mesh_check.cpp): 0 a random subset of a 5^3 lattice with repeats, 1 the integer
// points of one sphere, 2 three parallel planes, 3 lattice points of a cube's surface,
// 4 two concentric integer spheres.
#include <algorithm>
#include <random>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::test {

inline std::vector<Point3> degenerate_family(int family, int n, std::mt19937_64& rng) {
  std::vector<Point3> pts;
  std::uniform_int_distribution<int> small(0, 4);
  std::uniform_real_distribution<double> unit(-1, 1);
  switch (family) {
    case 0:  // a random subset of a 5^3 lattice, with repeats
      for (int i = 0; i < n; ++i) pts.push_back({double(small(rng)), double(small(rng)), double(small(rng))});
      break;
    case 1:  // integer points of one sphere
      for (int x = -9; x <= 9; ++x)
        for (int y = -9; y <= 9; ++y)
          for (int z = -9; z <= 9; ++z)
            if (x * x + y * y + z * z == 81) pts.push_back({double(x), double(y), double(z)});
      break;
    case 2:  // three parallel planes
      for (int i = 0; i < n; ++i) pts.push_back({double(small(rng) % 3), unit(rng), unit(rng)});
      break;
    case 3:  // lattice points of a cube's surface: coplanar hull facets everywhere
      for (int i = 0; i < n; ++i) {
        const int face = small(rng) % 6;
        const double a = small(rng), b = small(rng), c = (face & 1) ? 4 : 0;
        pts.push_back(face < 2 ? Point3{c, a, b} : face < 4 ? Point3{a, c, b} : Point3{a, b, c});
      }
      break;
    default:  // two concentric integer spheres
      for (int x = -5; x <= 5; ++x)
        for (int y = -5; y <= 5; ++y)
          for (int z = -5; z <= 5; ++z)
            if (x * x + y * y + z * z == 25 || x * x + y * y + z * z == 9)
              pts.push_back({double(x), double(y), double(z)});
      std::shuffle(pts.begin(), pts.end(), rng);
  }
  return pts;
}

}  // namespace dtlab::test
