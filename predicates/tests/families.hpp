#pragma once
// Input generators for the predicate tests: random points and the hard families of
// issue 3 (near-degenerate configurations that break floating point).
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::test {

using Quad = std::array<Point3, 4>;  // orient3d input
using Quint = std::array<Point3, 5>;  // insphere input

inline Point3 scaled(const Point3& p, int k) {
  return {std::ldexp(p.x, k), std::ldexp(p.y, k), std::ldexp(p.z, k)};
}

inline Point3 random_point(std::mt19937_64& rng, double lo = -1, double hi = 1) {
  std::uniform_real_distribution<double> u(lo, hi);
  return {u(rng), u(rng), u(rng)};
}

// The 3x4 affine map x -> M x + t, applied in double (each result rounded).
struct Affine {
  double m[3][3], t[3];
  Point3 operator()(const Point3& p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + t[0],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + t[1],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + t[2]};
  }
};

inline Affine random_affine(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  Affine a{};
  for (auto& row : a.m)
    for (double& v : row) v = u(rng);
  for (double& v : a.t) v = 100 * u(rng);
  return a;
}

// A random similarity (rotation from a random unit quaternion, scale, translation):
// maps spheres to spheres before rounding.
inline Affine random_similarity(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  double w = g(rng), x = g(rng), y = g(rng), z = g(rng);
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  std::uniform_real_distribution<double> u(-1, 1);
  const double s = std::exp2(4 * u(rng));
  Affine a{{{s * (1 - 2 * (y * y + z * z)), s * 2 * (x * y - z * w), s * 2 * (x * z + y * w)},
            {s * 2 * (x * y + z * w), s * (1 - 2 * (x * x + z * z)), s * 2 * (y * z - x * w)},
            {s * 2 * (x * z - y * w), s * 2 * (y * z + x * w), s * (1 - 2 * (x * x + y * y))}},
           {100 * u(rng), 100 * u(rng), 100 * u(rng)}};
  return a;
}

// Integer points on the sphere x^2 + y^2 + z^2 = 81 (exactly cospherical).
inline std::vector<Point3> sphere81_points() {
  std::vector<Point3> pts;
  for (int x = -9; x <= 9; ++x)
    for (int y = -9; y <= 9; ++y)
      for (int z = -9; z <= 9; ++z)
        if (x * x + y * y + z * z == 81) pts.push_back({double(x), double(y), double(z)});
  return pts;
}

inline Point3 small_int_point(std::mt19937_64& rng, int r) {
  std::uniform_int_distribution<int> u(-r, r);
  return {double(u(rng)), double(u(rng)), double(u(rng))};
}

// Exactly coplanar integer points: on the plane through p with integer spans u, v.
inline Quad coplanar_int_quad(std::mt19937_64& rng) {
  const Point3 p = small_int_point(rng, 50), u = small_int_point(rng, 20),
               v = small_int_point(rng, 20);
  std::uniform_int_distribution<int> k(-5, 5);
  Quad q;
  for (Point3& x : q) {
    const int s = k(rng), t = k(rng);
    x = {p.x + s * u.x + t * v.x, p.y + s * u.y + t * v.y, p.z + s * u.z + t * v.z};
  }
  return q;
}

// Five exactly cospherical integer points (distinct) translated by an integer offset.
inline Quint cospherical_int_quint(std::mt19937_64& rng) {
  static const std::vector<Point3> s = sphere81_points();
  std::uniform_int_distribution<std::size_t> pick(0, s.size() - 1);
  const Point3 o = small_int_point(rng, 1000);
  Quint q;
  for (int i = 0; i < 5; ++i) {
    bool fresh;
    do {
      q[i] = s[pick(rng)];
      fresh = true;
      for (int j = 0; j < i; ++j) fresh = fresh && !(q[j] == q[i]);
    } while (!fresh);
  }
  for (Point3& p : q) p = {p.x + o.x, p.y + o.y, p.z + o.z};
  return q;
}

// Moves one coordinate of one point by k ulps (k in [-3, 3]).
inline Point3 ulp_nudge(Point3 p, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> axis(0, 2), steps(-3, 3);
  const int a = axis(rng);
  double* c = a == 0 ? &p.x : (a == 1 ? &p.y : &p.z);
  const int k = steps(rng);
  for (int i = 0; i < std::abs(k); ++i) *c = std::nextafter(*c, k > 0 ? INFINITY : -INFINITY);
  return p;
}

// 3D version of Kettner et al.'s grid: point = 0.5 + (i, j, k) * 2^-53 near a plane
// and near a sphere through (0.5, 0.5, 0.5).
inline Point3 kettner_point(int i, int j, int k) {
  const double u = 0x1p-53;
  return {0.5 + i * u, 0.5 + j * u, 0.5 + k * u};
}
// Plane x = y through (12,12,12), (24,24,24), (24,24,0).
inline const Quad kKettnerPlane = {Point3{12, 12, 12}, Point3{24, 24, 24}, Point3{24, 24, 0},
                                   Point3{0, 0, 0}};
// Four points of the sphere centred at (12,12,12) through (0.5,0.5,0.5).
inline const Quad kKettnerSphere = {Point3{23.5, 23.5, 0.5}, Point3{23.5, 0.5, 23.5},
                                    Point3{0.5, 23.5, 23.5}, Point3{23.5, 23.5, 23.5}};

// All hard orient3d inputs of one family sweep (deterministic for a seed).
std::vector<Quad> hard_orient_inputs(std::uint64_t seed, int n);
std::vector<Quint> hard_insphere_inputs(std::uint64_t seed, int n);

}  // namespace dtlab::test
