#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <tuple>

#include "fuzz/generators.hpp"
#include "fuzz/lattice_solutions.hpp"

namespace dtlab::fuzz {

namespace {

struct LexLess {
  bool operator()(const Point3& a, const Point3& b) const { return lex_less(a, b); }
};
using PointSet = std::set<Point3, LexLess>;

Point3 add(const Point3& a, const Point3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }

Point3 random_int_point(Rng& rng, std::int64_t lo, std::int64_t hi) {
  const auto x = static_cast<double>(rng.range(lo, hi));
  const auto y = static_cast<double>(rng.range(lo, hi));
  const auto z = static_cast<double>(rng.range(lo, hi));
  return {x, y, z};
}

// Moves up to k random points of `pool` (translated by `offset`) that are not yet
// in `seen` to `out`.
void take_distinct(std::vector<Point3> pool, std::size_t k, const Point3& offset, Rng& rng,
                   PointSet& seen, std::vector<Point3>& out) {
  std::size_t taken = 0;
  for (std::size_t i = 0; i < pool.size() && taken < k; ++i) {
    std::swap(pool[i], pool[i + rng.below(pool.size() - i)]);
    const Point3 p = add(pool[i], offset);
    if (seen.insert(p).second) {
      out.push_back(p);
      ++taken;
    }
  }
}

// Places the circle (x, y, 0) in the plane perpendicular to coordinate axis `axis`.
Point3 orient_circle(const Point3& p, std::uint64_t axis) {
  if (axis == 0) return {p.z, p.x, p.y};
  if (axis == 1) return {p.y, p.z, p.x};
  return p;
}

std::int64_t smallest_rich_radius2(std::size_t count) {
  for (std::int64_t m : rich_circle_radii2())
    if (circle_lattice_points(m).size() >= count) return m;
  return rich_circle_radii2().back();
}

std::int64_t side_for(std::size_t volume) {
  std::int64_t k = 1;
  while (static_cast<std::size_t>(k * k * k) < volume) ++k;
  return k;
}

struct Int3 {
  std::int64_t x, y, z;
};
Int3 random_int3(Rng& rng, std::int64_t lo, std::int64_t hi) {
  const auto x = rng.range(lo, hi), y = rng.range(lo, hi), z = rng.range(lo, hi);
  return {x, y, z};
}
Int3 cross(const Int3& a, const Int3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
std::int64_t dot(const Int3& a, const Int3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Points o + s*w + i*u + j*v on `planes` parallel lattice planes spanned by u, v.
std::vector<Point3> plane_lattice(std::size_t n, std::int64_t planes, Rng& rng) {
  Int3 u, v, w;
  do {
    u = random_int3(rng, -3, 3);
    v = random_int3(rng, -3, 3);
  } while (dot(cross(u, v), cross(u, v)) == 0);
  do w = random_int3(rng, -5, 5);
  while (dot(cross(u, v), w) == 0);
  const Int3 o = random_int3(rng, -1000, 1000);
  const auto per_plane = static_cast<double>(2 * n) / static_cast<double>(planes);
  const auto half = static_cast<std::int64_t>(std::sqrt(per_plane) / 2) + 1;
  std::set<std::tuple<std::int64_t, std::int64_t, std::int64_t>> used;
  std::vector<Point3> out;
  out.reserve(n);
  while (out.size() < n) {
    const std::int64_t s = rng.range(0, planes - 1), i = rng.range(-half, half),
                       j = rng.range(-half, half);
    if (!used.insert({s, i, j}).second) continue;
    out.push_back({static_cast<double>(o.x + s * w.x + i * u.x + j * v.x),
                   static_cast<double>(o.y + s * w.y + i * u.y + j * v.y),
                   static_cast<double>(o.z + s * w.z + i * u.z + j * v.z)});
  }
  return out;
}

}  // namespace

std::vector<Point3> lattice_points(std::size_t n, Rng& rng) {
  const std::int64_t k = side_for(n);
  const Point3 offset = random_int_point(rng, -100, 100);
  std::vector<Point3> out;
  out.reserve(n);
  for (std::int64_t i = 0; i < k && out.size() < n; ++i)
    for (std::int64_t j = 0; j < k && out.size() < n; ++j)
      for (std::int64_t l = 0; l < k && out.size() < n; ++l)
        out.push_back(add({static_cast<double>(i), static_cast<double>(j), static_cast<double>(l)},
                          offset));
  rng.shuffle(out);
  return out;
}

std::vector<Point3> lattice_subset_points(std::size_t n, Rng& rng) {
  const std::int64_t k = std::max<std::int64_t>(2, side_for(4 * n));
  const Point3 offset = random_int_point(rng, -100, 100);
  std::vector<std::int64_t> cells(static_cast<std::size_t>(k * k * k));
  for (std::size_t c = 0; c < cells.size(); ++c) cells[c] = static_cast<std::int64_t>(c);
  std::vector<Point3> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::swap(cells[i], cells[i + rng.below(cells.size() - i)]);
    const std::int64_t c = cells[i];
    out.push_back(add({static_cast<double>(c / (k * k)), static_cast<double>(c / k % k),
                       static_cast<double>(c % k)},
                      offset));
  }
  return out;
}

std::vector<Point3> cospherical_points(std::size_t n, Rng& rng) {
  // One sphere holds up to 1024 of the points; beyond that, concentric shells.
  const Point3 centre = random_int_point(rng, -1000, 1000);
  PointSet seen;
  std::vector<Point3> out;
  out.reserve(n);
  std::int64_t r = 0;
  while (out.size() < n) {
    const std::size_t need = std::min<std::size_t>(n - out.size(), 1024);
    r = std::max(r + 1, sphere_radius_with(need));
    while (sphere_lattice_points(r).size() < need) ++r;
    take_distinct(sphere_lattice_points(r), need, centre, rng, seen, out);
  }
  rng.shuffle(out);
  return out;
}

std::vector<Point3> ring_points(std::size_t n, Rng& rng) {
  // Rings of at most 256 points, each in a plane perpendicular to a random axis
  // through its own random integer centre.
  const std::size_t rings = std::max<std::size_t>(2 + rng.below(3), (n + 255) / 256);
  const std::size_t share = std::max<std::size_t>(1, (n + rings - 1) / rings);
  PointSet seen;
  std::vector<Point3> out;
  out.reserve(n);
  while (out.size() < n) {
    const std::size_t need = std::min(share, n - out.size());
    const std::int64_t m = smallest_rich_radius2(2 * need);
    const std::uint64_t axis = rng.below(3);
    std::vector<Point3> pool = circle_lattice_points(m);
    for (auto& p : pool) p = orient_circle(p, axis);
    const auto span = static_cast<std::int64_t>(std::sqrt(static_cast<double>(m))) + 10;
    take_distinct(std::move(pool), need, random_int_point(rng, -span, span), rng, seen, out);
  }
  rng.shuffle(out);
  return out;
}

std::vector<Point3> cylinder_points(std::size_t n, Rng& rng) {
  // Coaxial rings of one radius at distinct integer heights: any two coaxial
  // circles lie on a common sphere, so the input is cocircular and cospherical
  // in bulk.
  const std::size_t rings = std::max<std::size_t>(2 + rng.below(4), (n + 511) / 512);
  const std::size_t share = std::max<std::size_t>(1, (n + rings - 1) / rings);
  const std::int64_t m = smallest_rich_radius2(share);
  const auto radius = static_cast<std::int64_t>(std::sqrt(static_cast<double>(m))) + 1;
  const Point3 centre = random_int_point(rng, -1000, 1000);
  const std::vector<Point3> circle = circle_lattice_points(m);
  PointSet seen;
  std::vector<Point3> out;
  out.reserve(n);
  std::int64_t height = rng.range(-radius, radius);
  while (out.size() < n) {
    const std::size_t need = std::min(share, n - out.size());
    take_distinct(circle, need, add(centre, {0, 0, static_cast<double>(height)}), rng, seen, out);
    height += rng.range(1, radius);
  }
  rng.shuffle(out);
  return out;
}

std::vector<Point3> coplanar_slab_points(std::size_t n, Rng& rng) {
  return plane_lattice(n, rng.range(2, 5), rng);
}

std::vector<Point3> coplanar_points(std::size_t n, Rng& rng) { return plane_lattice(n, 1, rng); }

std::vector<Point3> collinear_points(std::size_t n, Rng& rng) {
  // 1..4 lines o + t*d carry about 75% of the points; the rest are scattered.
  const std::size_t lines = 1 + rng.below(4);
  std::vector<Int3> origin(lines), dir(lines);
  for (std::size_t l = 0; l < lines; ++l) {
    origin[l] = random_int3(rng, -100, 100);
    do dir[l] = random_int3(rng, -4, 4);
    while (dot(dir[l], dir[l]) == 0);
  }
  const auto t_max = static_cast<std::int64_t>(n) + 4;
  PointSet seen;
  std::vector<Point3> out;
  out.reserve(n);
  while (out.size() < n) {
    Point3 p;
    if (rng.coin(0.75)) {
      const std::size_t l = rng.below(lines);
      const std::int64_t t = rng.range(-t_max, t_max);
      p = {static_cast<double>(origin[l].x + t * dir[l].x),
           static_cast<double>(origin[l].y + t * dir[l].y),
           static_cast<double>(origin[l].z + t * dir[l].z)};
    } else {
      p = random_int_point(rng, -200, 200);
    }
    if (seen.insert(p).second) out.push_back(p);
  }
  return out;
}

std::vector<Point3> exact_configuration(std::size_t n, Rng& rng) {
  switch (rng.below(4)) {
    case 0: return lattice_subset_points(n, rng);
    case 1: return cospherical_points(n, rng);
    case 2: return coplanar_slab_points(n, rng);
    default: return cylinder_points(n, rng);
  }
}

}  // namespace dtlab::fuzz
