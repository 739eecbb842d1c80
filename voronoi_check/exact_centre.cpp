#include "voronoi_check/exact_centre.hpp"

namespace dtlab {

namespace {

ExactPoint diff(const Point3& p, const Point3& o) {
  return {mpq_class(p.x) - mpq_class(o.x), mpq_class(p.y) - mpq_class(o.y), mpq_class(p.z) - mpq_class(o.z)};
}
ExactPoint cross(const ExactPoint& u, const ExactPoint& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
mpq_class dot(const ExactPoint& u, const ExactPoint& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

}  // namespace

ExactPoint exact_circumcentre(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  // x - a = (|u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v)) / (2 u.(v x w))
  const ExactPoint u = diff(b, a), v = diff(c, a), w = diff(d, a);
  const ExactPoint vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  const mpq_class den = 2 * dot(u, vw), uu = dot(u, u), vv = dot(v, v), ww = dot(w, w);
  const Point3 o = a;
  const double oc[3] = {o.x, o.y, o.z};
  ExactPoint x;
  for (int k = 0; k < 3; ++k) x[k] = mpq_class(oc[k]) + (uu * vw[k] + vv * wu[k] + ww * uv[k]) / den;
  return x;
}

bool all_collinear(std::span<const ExactPoint* const> points) {
  if (points.size() < 3) return true;
  const ExactPoint& o = *points[0];
  const ExactPoint* dir_end = nullptr;
  for (const ExactPoint* p : points)
    if (*p != o) {
      dir_end = p;
      break;
    }
  if (!dir_end) return true;
  const ExactPoint dir{(*dir_end)[0] - o[0], (*dir_end)[1] - o[1], (*dir_end)[2] - o[2]};
  for (const ExactPoint* p : points) {
    const ExactPoint c = cross(dir, {(*p)[0] - o[0], (*p)[1] - o[1], (*p)[2] - o[2]});
    if (sgn(c[0]) != 0 || sgn(c[1]) != 0 || sgn(c[2]) != 0) return false;
  }
  return true;
}

}  // namespace dtlab
