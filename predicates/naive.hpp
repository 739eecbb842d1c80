#pragma once
// The plain double-precision determinants: the thesis's first, failing version.
// Each is the textbook cofactor expansion after translating by the last point,
// evaluated in floating point with no error control.
#include <algorithm>
#include <string_view>

#include "predicates/backend.hpp"

namespace dtlab {

inline double orient3d_value(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  return adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) +
         cdx * (ady * bdz - adz * bdy);
}

// The insphere determinant and the largest lift |q - e|^2 of a,b,c,d (which the
// adaptive backend's semi-static filter bounds its error with). On the way the
// expansion along the lift column forms the four orientation minors: minor[k] is
// orient3d(a,b,c,d with its k-th point replaced by e), evaluated with orient3d_value's
// rounding count (the kernel's flip classification reads them). Always inlined: the
// callers are hot loops, and a call would return the struct through memory.
struct InsphereEval {
  double det;
  double max_lift;
  double minor[4];
};

[[gnu::always_inline]] inline InsphereEval insphere_eval(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                                  const Point3& e) {
  const double aex = a.x - e.x, aey = a.y - e.y, aez = a.z - e.z;
  const double bex = b.x - e.x, bey = b.y - e.y, bez = b.z - e.z;
  const double cex = c.x - e.x, cey = c.y - e.y, cez = c.z - e.z;
  const double dex = d.x - e.x, dey = d.y - e.y, dez = d.z - e.z;
  const double ab = aex * bey - bex * aey, bc = bex * cey - cex * bey;
  const double cd = cex * dey - dex * cey, da = dex * aey - aex * dey;
  const double ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
  const double abc = aez * bc - bez * ac + cez * ab;
  const double bcd = bez * cd - cez * bd + dez * bc;
  const double cda = cez * da + dez * ac + aez * cd;
  const double dab = dez * ab + aez * bd + bez * da;
  const double alift = aex * aex + aey * aey + aez * aez;
  const double blift = bex * bex + bey * bey + bez * bez;
  const double clift = cex * cex + cey * cey + cez * cez;
  const double dlift = dex * dex + dey * dey + dez * dez;
  const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  const double max_lift = std::max(std::max(alift, blift), std::max(clift, dlift));
  return {det, max_lift, {-bcd, cda, -dab, abc}};
}

inline double insphere_value(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                             const Point3& e) {
  return insphere_eval(a, b, c, d, e).det;
}

struct NaivePredicates {
  static constexpr std::string_view name() { return "naive"; }
  int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    return sign_of(orient3d_value(a, b, c, d));
  }
  int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
               const Point3& e) const {
    return sign_of(insphere_value(a, b, c, d, e));
  }
};

static_assert(PredicateBackend<NaivePredicates>);

}  // namespace dtlab
