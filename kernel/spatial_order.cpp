#include "kernel/spatial_order.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace dtlab {

// Skilling's transform ("Programming the Hilbert curve", 2004): undo the excess
// work of the axes-to-transpose recursion, Gray-encode, then interleave the bits.
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits) {
  std::uint32_t X[3] = {x, y, z};
  const std::uint32_t top = 1u << (bits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t low = q - 1;
    for (int i = 0; i < 3; ++i) {
      if (X[i] & q) {
        X[0] ^= low;
      } else {
        const std::uint32_t t = (X[0] ^ X[i]) & low;
        X[0] ^= t;
        X[i] ^= t;
      }
    }
  }
  X[1] ^= X[0];
  X[2] ^= X[1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (X[2] & q) t ^= q - 1;
  for (auto& c : X) c ^= t;
  std::uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < 3; ++i) key = (key << 1) | ((X[i] >> b) & 1u);
  return key;
}

void hilbert_sort(std::span<const Point3> points, std::span<std::uint32_t> indices) {
  if (indices.size() < 2) return;
  Point3 lo = points[indices[0]], hi = lo;
  for (std::uint32_t i : indices) {
    const Point3& p = points[i];
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  // Scale per axis into [0, 2^10): 2^30 cells, a thousand per point at 10^6 points,
  // is all the locality the walk needs. Extreme ranges only need to be ordered.
  constexpr int kBits = 10;
  constexpr double kMax = (1 << kBits) - 1;
  auto axis = [kMax](double v, double l, double h) -> std::uint32_t {
    const double range = h - l;
    if (!(range > 0) || !std::isfinite(range)) {
      const double r2 = h / 2 - l / 2;
      if (!(r2 > 0)) return 0;
      return static_cast<std::uint32_t>(std::min(kMax, (v / 2 - l / 2) / r2 * kMax));
    }
    return static_cast<std::uint32_t>(std::min(kMax, (v - l) / range * kMax));
  };
  // Key in the high 30 bits, index in the low 32: one integer sort.
  std::vector<std::uint64_t> keyed(indices.size());
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const Point3& p = points[indices[k]];
    const std::uint64_t key =
        hilbert_index(axis(p.x, lo.x, hi.x), axis(p.y, lo.y, hi.y), axis(p.z, lo.z, hi.z), kBits);
    keyed[k] = key << 32 | indices[k];
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t k = 0; k < indices.size(); ++k) indices[k] = static_cast<std::uint32_t>(keyed[k]);
}

std::vector<std::uint32_t> brio_order(std::span<const Point3> points, std::uint64_t seed) {
  std::vector<std::uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), 0u);
  std::mt19937_64 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  // Rounds [n/2^(k+1), n/2^k), the first one holding everything below 64 points.
  std::size_t end = order.size();
  while (end > 0) {
    const std::size_t begin = end > 128 ? end / 2 : 0;
    hilbert_sort(points, std::span<std::uint32_t>(order).subspan(begin, end - begin));
    end = begin;
  }
  return order;
}

}  // namespace dtlab
