#pragma once
// Circumcentres of tetrahedra: the Voronoi vertices of a Delaunay tetrahedralization.
#include "voronoi/box.hpp"

namespace dtlab::vor {

// The centre of the sphere through a, b, c, d, computed relative to a:
//   x - a = (|u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v)) / (2 u.(v x w)),
// u = b - a, v = c - a, w = d - a. Differences first keep the magnitudes local
// (no cancellation of large coordinates); the denominator is 12 times the volume, so
// a near-flat tet (a sliver of cospherical points) has a badly conditioned centre:
// `condition` returns |u||v||w| / |u.(v x w)|, the relative error amplification.
inline Point3 circumcenter(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                           double* condition = nullptr) {
  const Point3 u = b - a, v = c - a, w = d - a;
  const Point3 vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  const double den = 2 * dot(u, vw);
  if (condition) *condition = 2 * norm(u) * norm(v) * norm(w) / std::abs(den);
  const Point3 num = dot(u, u) * vw + dot(v, v) * wu + dot(w, w) * uv;
  return a + 1.0 / den * num;
}

}  // namespace dtlab::vor
