#include "fuzz/lattice_solutions.hpp"

#include <cmath>

namespace dtlab::fuzz {

namespace {

// floor(sqrt(v)) for 0 <= v < 2^62, exact (the double guess is corrected).
std::int64_t isqrt(std::int64_t v) {
  auto s = static_cast<std::int64_t>(std::sqrt(static_cast<double>(v)));
  while (s > 0 && s * s > v) --s;
  while ((s + 1) * (s + 1) <= v) ++s;
  return s;
}

}  // namespace

std::vector<Point3> sphere_lattice_points(std::int64_t r) {
  std::vector<Point3> out;
  const std::int64_t r2 = r * r;
  for (std::int64_t x = -r; x <= r; ++x) {
    const std::int64_t rest = r2 - x * x;
    const std::int64_t ymax = isqrt(rest);
    for (std::int64_t y = -ymax; y <= ymax; ++y) {
      const std::int64_t z2 = rest - y * y;
      const std::int64_t z = isqrt(z2);
      if (z * z != z2) continue;
      const auto dx = static_cast<double>(x), dy = static_cast<double>(y);
      if (z == 0) {
        out.push_back({dx, dy, 0.0});
      } else {
        out.push_back({dx, dy, static_cast<double>(-z)});
        out.push_back({dx, dy, static_cast<double>(z)});
      }
    }
  }
  return out;
}

std::int64_t sphere_radius_with(std::size_t count) {
  // r3(r^2) grows roughly like r, with large dips (powers of 2 only have 6), so
  // start below the typical size and walk up.
  std::int64_t r = 1 + static_cast<std::int64_t>(static_cast<double>(count) / 8.0);
  if (r > 1) r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(count))) + 1;
  for (;; ++r)
    if (sphere_lattice_points(r).size() >= count) return r;
}

std::vector<Point3> circle_lattice_points(std::int64_t m) {
  std::vector<Point3> out;
  const std::int64_t xmax = isqrt(m);
  for (std::int64_t x = -xmax; x <= xmax; ++x) {
    const std::int64_t y2 = m - x * x;
    const std::int64_t y = isqrt(y2);
    if (y * y != y2) continue;
    const auto dx = static_cast<double>(x);
    if (y == 0) {
      out.push_back({dx, 0.0, 0.0});
    } else {
      out.push_back({dx, static_cast<double>(-y), 0.0});
      out.push_back({dx, static_cast<double>(y), 0.0});
    }
  }
  return out;
}

const std::vector<std::int64_t>& rich_circle_radii2() {
  // 5, 5*13, 5*13*17, ... times 37, 41, 53, 61: each new prime doubles the count.
  static const std::vector<std::int64_t> radii = [] {
    std::vector<std::int64_t> v;
    std::int64_t m = 1;
    for (std::int64_t p : {5, 13, 17, 29, 37, 41, 53, 61}) {
      m *= p;
      v.push_back(m);
    }
    return v;
  }();
  return radii;
}

}  // namespace dtlab::fuzz
