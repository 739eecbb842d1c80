#include "oracle/check/hull_degree.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "predicates/error_bounds.hpp"

namespace dtlab {
namespace {

struct QPoint {
  mpq_class x, y, z;
};

QPoint to_q(const Point3& p) { return {mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)}; }

QPoint centroid(std::initializer_list<Point3> pts) {
  QPoint r{0, 0, 0};
  for (const Point3& p : pts) {
    r.x += mpq_class(p.x);
    r.y += mpq_class(p.y);
    r.z += mpq_class(p.z);
  }
  const mpq_class n(static_cast<long>(pts.size()));
  r.x /= n;
  r.y /= n;
  r.z /= n;
  return r;
}

// Sign of orient(o, a, b, q_e) = det [o-q_e; a-q_e; b-q_e] for the perturbed
// q_e = q + e*x + e^2*y + e^3*z, e -> 0+. Subtracting the first row from the others,
//   det = (o - q_e) . n,  n = (a - o) x (b - o),
// which is (o - q).n - e n_x - e^2 n_y - e^3 n_z: its sign is the first non-zero
// of (o - q).n, -n_x, -n_y, -n_z. It is zero for all e only when n = 0, that is
// o collinear with a and b; then 0 is returned (undecided).
int perturbed_orient(const QPoint& o, const Point3& a, const Point3& b, const QPoint& q) {
  const QPoint A = to_q(a), B = to_q(b);
  const mpq_class ax = A.x - o.x, ay = A.y - o.y, az = A.z - o.z;
  const mpq_class bx = B.x - o.x, by = B.y - o.y, bz = B.z - o.z;
  const mpq_class nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
  const int s = sgn((o.x - q.x) * nx + (o.y - q.y) * ny + (o.z - q.z) * nz);
  if (s != 0) return s;
  if (sgn(nx) != 0) return -sgn(nx);
  if (sgn(ny) != 0) return -sgn(ny);
  return -sgn(nz);
}

double norm_inf(double x, double y, double z) { return std::max({std::fabs(x), std::fabs(y), std::fabs(z)}); }

// Floating-point value of det [o-q; x-q; y-q] and a bound on its distance to the
// exact value with the exact o and q (whose doubles od, qd are within 1 ulp).
// Deliberately loose: 64 times the first-order rounding terms. The bound assumes no
// underflow or overflow (at extents near 2^-350 it underflows while the value still
// carries error), so, as in filtered_exact.cpp, it is only trusted when every
// non-zero difference lies in [2^-140, 2^140]: then every product of three lies in
// [2^-420, 2^420] and the bound is a normal number. Otherwise the exact code answers.
struct Approx {
  double value, err;
  bool trusted;
};

Approx approx_orient(const Point3& od, const Point3& x, const Point3& y, const Point3& qd) {
  const double ax = od.x - qd.x, ay = od.y - qd.y, az = od.z - qd.z;
  const double bx = x.x - qd.x, by = x.y - qd.y, bz = x.z - qd.z;
  const double cx = y.x - qd.x, cy = y.y - qd.y, cz = y.z - qd.z;
  bool trusted = true;
  for (double d : {ax, ay, az, bx, by, bz, cx, cy, cz})
    if (!error_bounds::in_safe_range(d)) trusted = false;
  for (double c : {od.x, od.y, od.z, qd.x, qd.y, qd.z})
    if (!(std::fabs(c) <= error_bounds::kSafeHigh)) trusted = false;
  if (!trusted) return {0, 0, false};
  const double v = ax * (by * cz - bz * cy) + bx * (cy * az - cz * ay) + cx * (ay * bz - az * by);
  const double L = std::max({norm_inf(ax, ay, az), norm_inf(bx, by, bz), norm_inf(cx, cy, cz)});
  const double M = norm_inf(od.x, od.y, od.z) + norm_inf(qd.x, qd.y, qd.z) + L;
  const double err = 64.0 * (2 * error_bounds::kEps) * (6.0 * L * L * L + 12.0 * M * L * L);
  return {v, err, true};
}

}  // namespace

// Why this always decides: o is strictly on the inner side of every boundary facet's
// plane (the caller's precondition), so for each facet edge (a, b) the points o, a, b
// are not collinear (a != b, and a line through o meeting the plane of the facet in
// two points would lie in it), n != 0 in perturbed_orient, and every sign is non-zero.
// For all small enough e > 0 these finitely many polynomial signs are constant and
// non-zero, so the ray towards q_e misses every edge and crosses exactly the facets
// that the perturbed signs say: a regular value of the projection, whose preimage
// count is the degree. No retry loop is needed, so the computation terminates after
// one pass over the facets.
HullDegree hull_degree(std::span<const Point3> points, std::span<const std::array<std::uint32_t, 3>> boundary,
                       const Tet& inner_tet, std::uint32_t f0) {
  HullDegree out;
  const auto& F0 = boundary[f0];
  const QPoint o = centroid({points[inner_tet[0]], points[inner_tet[1]], points[inner_tet[2]], points[inner_tet[3]]});
  const QPoint q = centroid({points[F0[0]], points[F0[1]], points[F0[2]]});
  const Point3 od{o.x.get_d(), o.y.get_d(), o.z.get_d()};
  const Point3 qd{q.x.get_d(), q.y.get_d(), q.z.get_d()};
  // The ray o->q_e crosses facet (a,b,c) iff q_e lies strictly inside the three
  // planes (o, a, b), (o, b, c), (o, c, a) (a cone from o, not a double cone): the
  // perturbed det [o-q_e; a-q_e; b-q_e] < 0 for each edge (a, b) of the
  // outward-oriented facet.
  for (std::size_t g = 0; g < boundary.size(); ++g) {
    const auto& f = boundary[g];
    bool maybe = true;
    for (int e = 0; e < 3 && maybe; ++e) {
      // A certainly positive unperturbed value stays positive under the perturbation.
      const Approx a = approx_orient(od, points[f[e]], points[f[(e + 1) % 3]], qd);
      if (a.trusted && a.value > a.err) maybe = false;
    }
    if (!maybe) continue;
    int neg = 0;
    for (int e = 0; e < 3; ++e) {
      const int s = perturbed_orient(o, points[f[e]], points[f[(e + 1) % 3]], q);
      if (s == 0) return out;  // precondition violated: undecided
      neg += s < 0;
    }
    if (neg == 3) out.crossed.push_back(static_cast<std::uint32_t>(g));
  }
  // f0 first.
  auto it = std::find(out.crossed.begin(), out.crossed.end(), f0);
  if (it != out.crossed.end()) std::rotate(out.crossed.begin(), it, it + 1);
  out.decided = true;
  return out;
}

}  // namespace dtlab
