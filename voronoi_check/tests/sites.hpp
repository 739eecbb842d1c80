#pragma once
// Sites and the box shared by the Voronoi checker's tests.
#include <random>
#include <vector>

#include "voronoi/box.hpp"

namespace dtlab::test {

// n sites uniform in the unit cube, reproducible from the seed.
inline std::vector<Point3> random_sites(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point3> p(n);
  for (auto& q : p) q = {u(rng), u(rng), u(rng)};
  return p;
}

// The unit cube with a margin of 0.1: every cell is clipped, none is empty.
inline const vor::Box kBox{{-0.1, -0.1, -0.1}, {1.1, 1.1, 1.1}};

}  // namespace dtlab::test
