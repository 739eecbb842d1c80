#pragma once
// Seeded uniform points in [-1, 1]^3, the kernel tests' general-position input.
#include <cstdint>
#include <random>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::test {

inline std::vector<Point3> uniform(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Point3> pts(n);
  for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
  return pts;
}

}  // namespace dtlab::test
