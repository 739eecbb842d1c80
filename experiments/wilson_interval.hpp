#pragma once
// Wilson's 95% score interval for a binomial proportion k/n (Wilson 1927): unlike
// k/n +- 1.96 sd it stays inside [0, 1] and is not empty at k = 0 or k = n.
#include <algorithm>
#include <cmath>
#include <utility>

namespace dtlab::experiments {

inline std::pair<double, double> wilson_interval(std::size_t k, std::size_t n, double z = 1.959964) {
  if (n == 0) return {0.0, 1.0};
  const double p = static_cast<double>(k) / static_cast<double>(n), nn = static_cast<double>(n);
  const double center = (p + z * z / (2 * nn)) / (1 + z * z / nn);
  const double half = z * std::sqrt(p * (1 - p) / nn + z * z / (4 * nn * nn)) / (1 + z * z / nn);
  return {std::max(0.0, center - half), std::min(1.0, center + half)};
}

}  // namespace dtlab::experiments
