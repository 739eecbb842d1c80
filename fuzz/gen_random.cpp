#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>

#include "fuzz/generators.hpp"

namespace dtlab::fuzz {

std::vector<Point3> uniform_points(std::size_t n, Rng& rng) {
  std::vector<Point3> out(n);
  for (auto& p : out) p = {rng.unit(), rng.unit(), rng.unit()};
  return out;
}

std::vector<Point3> clustered_points(std::size_t n, Rng& rng) {
  // 1..6 clusters in the unit cube, radii 2^-4 .. 2^-40: wildly different local
  // densities and near-coincident points inside the tightest clusters.
  const std::size_t clusters = 1 + rng.below(6);
  std::vector<Point3> centre(clusters);
  std::vector<double> radius(clusters);
  for (std::size_t c = 0; c < clusters; ++c) {
    centre[c] = {rng.unit(), rng.unit(), rng.unit()};
    radius[c] = std::ldexp(1.0, -static_cast<int>(rng.range(4, 40)));
  }
  std::vector<Point3> out(n);
  for (auto& p : out) {
    const std::size_t c = rng.below(clusters);
    const double r = radius[c];
    const double x = rng.gaussianish(), y = rng.gaussianish(), z = rng.gaussianish();
    p = {centre[c].x + r * x, centre[c].y + r * y, centre[c].z + r * z};
  }
  return out;
}

std::vector<Point3> duplicate_points(std::size_t n, Rng& rng) {
  // About 30% of the points repeat an earlier one. A fifth of the coordinates are
  // zero, and a repeat flips the sign of its zeros: -0.0 == 0.0, so it is still
  // the same point, a classic trap for duplicate detection by bit pattern.
  const bool on_lattice = rng.coin(0.5);
  std::vector<Point3> out;
  out.reserve(n);
  const auto coord = [&] {
    if (rng.coin(0.2)) return 0.0;
    return on_lattice ? static_cast<double>(rng.range(-8, 8)) : rng.uniform(-1, 1);
  };
  const auto flip_zero = [](double v) { return v == 0 ? -v : v; };
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0 && rng.coin(0.3)) {
      Point3 q = out[rng.below(i)];
      if (rng.coin(0.5)) q = {flip_zero(q.x), flip_zero(q.y), flip_zero(q.z)};
      out.push_back(q);
    } else {
      const double x = coord(), y = coord(), z = coord();
      out.push_back({x, y, z});
    }
  }
  return out;
}

std::vector<Point3> moment_curve_points(std::size_t n, Rng& rng) {
  // (t, t^2, t^3) for distinct integers t in [1, T]; t^3 < 2^53 keeps every
  // coordinate exact, so T <= 208063, and beyond n = 208063 values repeat.
  const std::int64_t t_max =
      std::min<std::int64_t>(208063, std::max<std::int64_t>(8, 2 * static_cast<std::int64_t>(n)));
  std::set<std::int64_t> used;
  std::vector<Point3> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::int64_t t = rng.range(1, t_max);
    if (used.size() < static_cast<std::size_t>(t_max))
      while (!used.insert(t).second) t = rng.range(1, t_max);
    const auto d = static_cast<double>(t);
    out.push_back({d, d * d, d * d * d});
  }
  return out;
}

}  // namespace dtlab::fuzz
