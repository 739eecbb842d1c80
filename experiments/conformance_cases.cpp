#include "experiments/conformance_cases.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace dtlab::experiments {
namespace {

using Quad = std::array<Point3, 4>;
using Quint = std::array<Point3, 5>;

Point3 add(const Point3& p, const Point3& q, double s) { return {p.x + s * q.x, p.y + s * q.y, p.z + s * q.z}; }
Point3 scaled(const Point3& p, int k) { return {std::ldexp(p.x, k), std::ldexp(p.y, k), std::ldexp(p.z, k)}; }

struct Gen {
  std::mt19937_64 rng;
  double uniform() { return std::uniform_real_distribution<double>(-1, 1)(rng); }
  int integer(int r) { return std::uniform_int_distribution<int>(-r, r)(rng); }
  Point3 point() { return {uniform(), uniform(), uniform()}; }
  Point3 int_point(int r) { return {double(integer(r)), double(integer(r)), double(integer(r))}; }
  Point3 nudged(Point3 p) {  // one coordinate moved by 1..64 ulps
    double* c[3] = {&p.x, &p.y, &p.z};
    double& v = *c[integer(1) + 1];
    const int k = std::uniform_int_distribution<int>(1, 64)(rng) * (integer(1) < 0 ? -1 : 1);
    for (int i = 0; i < std::abs(k); ++i) v = std::nextafter(v, k > 0 ? INFINITY : -INFINITY);
    return p;
  }
  // a, b, c spanning a plane and d on it: integer combinations, exact in doubles.
  Quad coplanar() {
    const Point3 a = int_point(1000), u = int_point(100), v = int_point(100);
    return {a, add(a, u, 1), add(a, v, 1), add(add(a, u, integer(5)), v, integer(5))};
  }
  // Five distinct points of the integer sphere x^2 + y^2 + z^2 = 81 around an integer centre.
  Quint cospherical() {
    static const std::vector<Point3> sphere = [] {
      std::vector<Point3> s;
      for (int x = -9; x <= 9; ++x)
        for (int y = -9; y <= 9; ++y)
          for (int z = -9; z <= 9; ++z)
            if (x * x + y * y + z * z == 81) s.push_back({double(x), double(y), double(z)});
      return s;
    }();
    const Point3 centre = int_point(1000);
    Quint q;
    for (std::size_t i = 0; i < 5; ++i)
      do q[i] = add(centre, sphere[std::uniform_int_distribution<std::size_t>(0, sphere.size() - 1)(rng)], 1);
      while (std::find(q.begin(), q.begin() + i, q[i]) != q.begin() + i);
    return q;
  }
};

Quad near_coplanar(Gen& g) {  // d = a + s (b - a) + t (c - a), rounded: within ulps of the plane
  const Point3 a = g.point(), b = g.point(), c = g.point();
  const double s = g.uniform(), t = g.uniform();
  return {a, b, c, {a.x + s * (b.x - a.x) + t * (c.x - a.x), a.y + s * (b.y - a.y) + t * (c.y - a.y),
                    a.z + s * (b.z - a.z) + t * (c.z - a.z)}};
}

Quint near_cospherical(Gen& g) {  // unit vectors, rounded: within ulps of the unit sphere
  Quint q;
  for (Point3& p : q) {
    const Point3 v = g.point();
    const double r = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    p = {v.x / r, v.y / r, v.z / r};
  }
  return q;
}

// Kettner et al.'s grid: points 0..15 ulps from (0.5, 0.5) against the plane x = y.
Quad kettner(Gen& g) {
  const double u = std::ldexp(1.0, -53);
  const Point3 d{0.5 + g.integer(8) * u + 8 * u, 0.5 + g.integer(8) * u + 8 * u, double(g.integer(4))};
  return {Point3{12, 12, 0}, Point3{24, 24, 0}, Point3{12, 12, 1}, d};
}

template <class T>
std::vector<T> scale_all(std::vector<T> v, int k) {
  for (auto& q : v)
    for (Point3& p : q) p = scaled(p, k);
  return v;
}

}  // namespace

std::vector<PredicateCases> conformance_cases(std::size_t n, std::uint64_t seed) {
  Gen g{std::mt19937_64(seed)};
  PredicateCases random{"random", {}, {}}, near{"near-degenerate", {}, {}}, exact{"exactly-degenerate", {}, {}},
      ulp{"ulp-nudged", {}, {}}, grid{"kettner-grid", {}, {}};
  for (std::size_t i = 0; i < n; ++i) {
    random.orient.push_back({g.point(), g.point(), g.point(), g.point()});
    random.insphere.push_back({g.point(), g.point(), g.point(), g.point(), g.point()});
    near.orient.push_back(near_coplanar(g));
    near.insphere.push_back(near_cospherical(g));
    exact.orient.push_back(g.coplanar());
    exact.insphere.push_back(g.cospherical());
    Quad o = g.coplanar();
    o[3] = g.nudged(o[3]);
    ulp.orient.push_back(o);
    Quint s = g.cospherical();
    s[4] = g.nudged(s[4]);
    ulp.insphere.push_back(s);
    grid.orient.push_back(kettner(g));
  }
  std::vector<PredicateCases> out = {random, near, exact, ulp, grid};
  for (int k : {500, -500})
    for (const PredicateCases* c : {&near, &exact, &ulp})
      out.push_back({c->case_class + " x2^" + std::to_string(k), scale_all(c->orient, k), scale_all(c->insphere, k)});
  return out;
}

}  // namespace dtlab::experiments
