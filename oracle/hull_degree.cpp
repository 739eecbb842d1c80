#include "oracle/hull_degree.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>

namespace dtlab {
namespace {

struct QPoint {
  mpq_class x, y, z;
};

QPoint to_q(const Point3& p) { return {mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)}; }

QPoint combine(std::span<const Point3> pts, std::span<const int> w) {
  QPoint r{0, 0, 0};
  int total = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    r.x += w[i] * mpq_class(pts[i].x);
    r.y += w[i] * mpq_class(pts[i].y);
    r.z += w[i] * mpq_class(pts[i].z);
    total += w[i];
  }
  r.x /= total;
  r.y /= total;
  r.z /= total;
  return r;
}

// sign det [a-d; b-d; c-d], exactly.
int orient_q(const QPoint& a, const QPoint& b, const QPoint& c, const QPoint& d) {
  const mpq_class ax = a.x - d.x, ay = a.y - d.y, az = a.z - d.z;
  const mpq_class bx = b.x - d.x, by = b.y - d.y, bz = b.z - d.z;
  const mpq_class cx = c.x - d.x, cy = c.y - d.y, cz = c.z - d.z;
  const mpq_class det = ax * (by * cz - bz * cy) + bx * (cy * az - cz * ay) + cx * (ay * bz - az * by);
  return sgn(det);
}

double norm_inf(double x, double y, double z) { return std::max({std::fabs(x), std::fabs(y), std::fabs(z)}); }

// Floating-point value of det [o-q; x-q; y-q] and a bound on its distance to the
// exact value with the exact o and q (whose doubles od, qd are within 1 ulp).
// Deliberately loose: 64 times the first-order rounding terms.
struct Approx {
  double value, err;
};

Approx approx_orient(const Point3& od, const Point3& x, const Point3& y, const Point3& qd) {
  const double ax = od.x - qd.x, ay = od.y - qd.y, az = od.z - qd.z;
  const double bx = x.x - qd.x, by = x.y - qd.y, bz = x.z - qd.z;
  const double cx = y.x - qd.x, cy = y.y - qd.y, cz = y.z - qd.z;
  const double v = ax * (by * cz - bz * cy) + bx * (cy * az - cz * ay) + cx * (ay * bz - az * by);
  const double L = std::max({norm_inf(ax, ay, az), norm_inf(bx, by, bz), norm_inf(cx, cy, cz)});
  const double M = norm_inf(od.x, od.y, od.z) + norm_inf(qd.x, qd.y, qd.z) + L;
  const double err = 64.0 * 0x1p-52 * (6.0 * L * L * L + 12.0 * M * L * L);
  return {v, err};
}

}  // namespace

HullDegree hull_degree(std::span<const Point3> points,
                       std::span<const std::array<std::uint32_t, 3>> boundary,
                       const Tet& inner_tet, std::uint32_t f0) {
  HullDegree out;
  const Point3 tet_pts[4] = {points[inner_tet[0]], points[inner_tet[1]], points[inner_tet[2]],
                             points[inner_tet[3]]};
  const auto& F0 = boundary[f0];
  const Point3 f0_pts[3] = {points[F0[0]], points[F0[1]], points[F0[2]]};
  for (int attempt = 0; attempt < 8; ++attempt) {
    const int wo[4] = {1 + attempt, 2, 3 + 2 * attempt, 5 + attempt * attempt};
    const int wq[3] = {1, 2 + attempt, 4 + 3 * attempt};
    const QPoint o = combine(tet_pts, wo), q = combine(f0_pts, wq);
    const Point3 od{o.x.get_d(), o.y.get_d(), o.z.get_d()};
    const Point3 qd{q.x.get_d(), q.y.get_d(), q.z.get_d()};
    // The ray o->q crosses facet (a,b,c) iff q lies strictly inside the three
    // planes (o, a, b), (o, b, c), (o, c, a): det [o-q; a-q; b-q] < 0 for each
    // edge (a, b) of the outward-oriented facet (see README).
    bool degenerate = false;
    std::vector<std::uint32_t> crossed;
    for (std::size_t g = 0; g < boundary.size() && !degenerate; ++g) {
      const auto& f = boundary[g];
      bool maybe = true;
      for (int e = 0; e < 3 && maybe; ++e) {
        const Approx a = approx_orient(od, points[f[e]], points[f[(e + 1) % 3]], qd);
        if (a.value > a.err) maybe = false;
      }
      if (!maybe) continue;
      int neg = 0, zero = 0;
      for (int e = 0; e < 3; ++e) {
        const int s = orient_q(o, to_q(points[f[e]]), to_q(points[f[(e + 1) % 3]]), q);
        neg += s < 0;
        zero += s == 0;
      }
      if (neg == 3) crossed.push_back(static_cast<std::uint32_t>(g));
      else if (zero > 0 && neg + zero == 3) degenerate = true;
    }
    if (degenerate) continue;
    // f0 first.
    auto it = std::find(crossed.begin(), crossed.end(), f0);
    if (it != crossed.end()) std::rotate(crossed.begin(), it, it + 1);
    out.decided = true;
    out.crossed = std::move(crossed);
    return out;
  }
  return out;
}

}  // namespace dtlab
