#pragma once
// Seeded uniform points in [lo, hi]^3 ([-1, 1]^3 unless told): the general-position
// input of the kernel, Voronoi, checker and Voronoi-checker tests (header-only; the
// include root is the source folder, so any module's tests include it).
#include <cstdint>
#include <random>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::test {

inline std::vector<Point3> uniform(std::size_t n, std::uint64_t seed, double lo = -1, double hi = 1) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<Point3> pts(n);
  for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
  return pts;
}

}  // namespace dtlab::test
