#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <tuple>

#include "fuzz/generators.hpp"
#include "fuzz/rounded_transform.hpp"

namespace dtlab::fuzz {

std::vector<Point3> near_degenerate_points(std::size_t n, Rng& rng) {
  std::vector<Point3> out = exact_configuration(n, rng);
  const RoundedTransform t = random_transform(rng);
  for (auto& p : out) p = t.apply(p);
  return out;
}

std::vector<Point3> ulp_jitter_points(std::size_t n, Rng& rng) {
  // Each coordinate moves to a neighbouring double with probability 2/3.
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<Point3> out = exact_configuration(n, rng);
  const auto jitter = [&](double v) {
    switch (rng.below(3)) {
      case 0: return std::nextafter(v, -inf);
      case 1: return std::nextafter(v, inf);
      default: return v;
    }
  };
  for (auto& p : out) {
    const double x = jitter(p.x), y = jitter(p.y), z = jitter(p.z);
    p = {x, y, z};
  }
  return out;
}

std::vector<Point3> extreme_scale_points(std::size_t n, Rng& rng) {
  // Scaling by 2^k is exact (no coordinate leaves the normal range: integers
  // below 2^22 times 2^-500 .. 2^500), so every predicate sign is unchanged, while
  // plain double determinants overflow to inf or underflow to zero.
  std::vector<Point3> out = exact_configuration(n, rng);
  const int k = static_cast<int>(rng.range(-500, 500));
  for (auto& p : out) p = {std::ldexp(p.x, k), std::ldexp(p.y, k), std::ldexp(p.z, k)};
  return out;
}

std::vector<Point3> far_translate_points(std::size_t n, Rng& rng) {
  // A box 2^2 .. 2^12 ulps wide around a centre 2^30 .. 2^40 from the origin:
  // coordinates snap to a coarse grid of doubles, creating accidental
  // coplanarities and cosphericities in a point set that looks random.
  const auto centre_coord = [&] {
    const double c = std::ldexp(1.0 + rng.unit(), static_cast<int>(rng.range(30, 39)));
    return rng.coin(0.5) ? -c : c;
  };
  const double cx = centre_coord(), cy = centre_coord(), cz = centre_coord();
  const double ulp = std::nextafter(std::abs(cx), std::numeric_limits<double>::infinity()) -
                     std::abs(cx);
  const double width = ulp * std::ldexp(1.0, static_cast<int>(rng.range(2, 12)));
  std::vector<Point3> out(n);
  for (auto& p : out) {
    const double x = cx + width * rng.unit(), y = cy + width * rng.unit(),
                 z = cz + width * rng.unit();
    p = {x, y, z};
  }
  return out;
}

std::vector<Point3> subnormal_points(std::size_t n, Rng& rng) {
  // Integers below 2^22 times 2^-1060 are multiples of 2^-1074 below 2^-1038:
  // exact subnormals, so the configuration stays exactly degenerate while every
  // product in a plain double determinant underflows to zero.
  std::vector<Point3> out = exact_configuration(n, rng);
  for (auto& p : out) p = {std::ldexp(p.x, -1060), std::ldexp(p.y, -1060), std::ldexp(p.z, -1060)};
  return out;
}

std::vector<Point3> kettner_grid_points(std::size_t n, Rng& rng) {
  // Kettner et al.'s classroom example in 3D: a 256^3 grid of doubles
  // 0.5 + i * 2^-53 next to the line x = y = z and the plane x - 2y + z = 0
  // spanned by the anchors, so orient3d's true value is tiny for most quadruples.
  std::vector<Point3> out;
  out.reserve(n);
  for (std::size_t a = 0; a < 4 && out.size() < n; ++a) out.push_back(kKettnerAnchors[a]);
  std::set<std::tuple<std::int64_t, std::int64_t, std::int64_t>> used;
  const auto grid = [&] { return rng.range(0, kKettnerSide - 1); };
  while (out.size() < n) {
    const std::int64_t i = grid(), j = grid(), k = grid();
    // Beyond 256^3 grid points the grid is full and points repeat.
    if (!used.insert({i, j, k}).second && used.size() < std::size_t{1} << 24) continue;
    out.push_back({kKettnerBase + static_cast<double>(i) * kKettnerStep,
                   kKettnerBase + static_cast<double>(j) * kKettnerStep,
                   kKettnerBase + static_cast<double>(k) * kKettnerStep});
  }
  rng.shuffle(out);
  return out;
}

}  // namespace dtlab::fuzz
