#pragma once
// The naive determinants evaluated in a wider floating-point type: `long-double`
// (x87 extended, 64-bit significand) and `float128` (IEEE binary128, 113-bit, GCC's
// software __float128). The same formulas as naive.hpp, the coordinates converted
// exactly to the wider type first. They ask whether more precision fixes robustness
// (Kettner et al., "Classroom examples of robustness problems in geometric
// computations": it does not, it moves the failures to closer configurations).
#include <string_view>

#include "predicates/backend.hpp"

namespace dtlab {

template <class Real>
int wide_orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const Real adx = Real(a.x) - Real(d.x), ady = Real(a.y) - Real(d.y), adz = Real(a.z) - Real(d.z);
  const Real bdx = Real(b.x) - Real(d.x), bdy = Real(b.y) - Real(d.y), bdz = Real(b.z) - Real(d.z);
  const Real cdx = Real(c.x) - Real(d.x), cdy = Real(c.y) - Real(d.y), cdz = Real(c.z) - Real(d.z);
  const Real det = adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) + cdx * (ady * bdz - adz * bdy);
  return (det > 0) - (det < 0);
}

template <class Real>
int wide_insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
  const Real aex = Real(a.x) - Real(e.x), aey = Real(a.y) - Real(e.y), aez = Real(a.z) - Real(e.z);
  const Real bex = Real(b.x) - Real(e.x), bey = Real(b.y) - Real(e.y), bez = Real(b.z) - Real(e.z);
  const Real cex = Real(c.x) - Real(e.x), cey = Real(c.y) - Real(e.y), cez = Real(c.z) - Real(e.z);
  const Real dex = Real(d.x) - Real(e.x), dey = Real(d.y) - Real(e.y), dez = Real(d.z) - Real(e.z);
  const Real ab = aex * bey - bex * aey, bc = bex * cey - cex * bey;
  const Real cd = cex * dey - dex * cey, da = dex * aey - aex * dey;
  const Real ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
  const Real abc = aez * bc - bez * ac + cez * ab;
  const Real bcd = bez * cd - cez * bd + dez * bc;
  const Real cda = cez * da + dez * ac + aez * cd;
  const Real dab = dez * ab + aez * bd + bez * da;
  const Real alift = aex * aex + aey * aey + aez * aez;
  const Real blift = bex * bex + bey * bey + bez * bez;
  const Real clift = cex * cex + cey * cey + cez * cez;
  const Real dlift = dex * dex + dey * dey + dez * dez;
  const Real det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  return (det > 0) - (det < 0);
}

struct LongDoublePredicates {
  static constexpr std::string_view name() { return "long-double"; }
  int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    return wide_orient3d<long double>(a, b, c, d);
  }
  int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) const {
    return wide_insphere<long double>(a, b, c, d, e);
  }
};

struct Float128Predicates {
  static constexpr std::string_view name() { return "float128"; }
  int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    return wide_orient3d<__float128>(a, b, c, d);
  }
  int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) const {
    return wide_insphere<__float128>(a, b, c, d, e);
  }
};

static_assert(PredicateBackend<LongDoublePredicates>);
static_assert(PredicateBackend<Float128Predicates>);

}  // namespace dtlab
