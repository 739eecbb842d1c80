#pragma once
// Circumcentres of tetrahedra: the Voronoi vertices of a Delaunay tetrahedralization.
#include "voronoi/vec.hpp"

namespace dtlab::vor {

// The centre of the sphere through a, b, c, d, computed relative to a:
//   x - a = (|u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v)) / (2 u.(v x w)),
// u = b - a, v = c - a, w = d - a. Differences first keep the magnitudes local
// (no cancellation of large coordinates); the denominator is 12 times the volume, so
// a near-flat tet (a sliver of cospherical points) has a badly conditioned centre:
// `condition` returns |u||v||w| / |u.(v x w)|, the relative error amplification.
inline Point3 circumcenter(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                           double* condition = nullptr) {
  const Point3 u = vsub(b, a), v = vsub(c, a), w = vsub(d, a);
  const Point3 vw = vcross(v, w), wu = vcross(w, u), uv = vcross(u, v);
  const double den = 2 * vdot(u, vw);
  if (condition) *condition = 2 * vnorm(u) * vnorm(v) * vnorm(w) / std::abs(den);
  const Point3 num = vadd(vadd(vscale(vdot(u, u), vw), vscale(vdot(v, v), wu)), vscale(vdot(w, w), uv));
  return vadd(a, vscale(1.0 / den, num));
}

}  // namespace dtlab::vor
