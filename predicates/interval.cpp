#include "predicates/interval.hpp"

#include <boost/numeric/interval.hpp>

#include "predicates/exact.hpp"

namespace dtlab {
namespace {

namespace bi = boost::numeric::interval_lib;
// Upward rounding set once per predicate call (Guard) and lower bounds by negation
// (rounded_arith_opp), so the operations themselves switch no mode; no checking of
// empty intervals: the inputs are finite doubles.
using Rounding = bi::rounded_arith_opp<double>;
using Guard = bi::save_state<Rounding>;  // sets the mode for its scope, restores it after
using I = boost::numeric::interval<double, bi::policies<bi::save_state_nothing<Rounding>, bi::checking_base<double>>>;

// The sign of an interval, or 0 with *decided = false when it holds zero (or is not
// finite: an overflow leaves the sign to GMP).
int sign_of(const I& v, bool* decided) {
  *decided = true;
  if (v.lower() > 0 && v.upper() < bi::checking_base<double>::pos_inf()) return 1;
  if (v.upper() < 0 && v.lower() > bi::checking_base<double>::neg_inf()) return -1;
  *decided = false;
  return 0;
}

}  // namespace

int interval_orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d, bool* decided) {
  const Guard guard;
  const I adx = I(a.x) - d.x, ady = I(a.y) - d.y, adz = I(a.z) - d.z;
  const I bdx = I(b.x) - d.x, bdy = I(b.y) - d.y, bdz = I(b.z) - d.z;
  const I cdx = I(c.x) - d.x, cdy = I(c.y) - d.y, cdz = I(c.z) - d.z;
  return sign_of(adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) + cdx * (ady * bdz - adz * bdy), decided);
}

int interval_insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e,
                      bool* decided) {
  const Guard guard;
  const I aex = I(a.x) - e.x, aey = I(a.y) - e.y, aez = I(a.z) - e.z;
  const I bex = I(b.x) - e.x, bey = I(b.y) - e.y, bez = I(b.z) - e.z;
  const I cex = I(c.x) - e.x, cey = I(c.y) - e.y, cez = I(c.z) - e.z;
  const I dex = I(d.x) - e.x, dey = I(d.y) - e.y, dez = I(d.z) - e.z;
  const I ab = aex * bey - bex * aey, bc = bex * cey - cex * bey;
  const I cd = cex * dey - dex * cey, da = dex * aey - aex * dey;
  const I ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
  const I abc = aez * bc - bez * ac + cez * ab;
  const I bcd = bez * cd - cez * bd + dez * bc;
  const I cda = cez * da + dez * ac + aez * cd;
  const I dab = dez * ab + aez * bd + bez * da;
  const I alift = square(aex) + square(aey) + square(aez);
  const I blift = square(bex) + square(bey) + square(bez);
  const I clift = square(cex) + square(cey) + square(cez);
  const I dlift = square(dex) + square(dey) + square(dez);
  return sign_of((dlift * abc - clift * dab) + (blift * cda - alift * bcd), decided);
}

int IntervalPredicates::orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
  bool decided = false;
  const int s = interval_orient3d(a, b, c, d, &decided);
  return decided ? s : exact_orient3d(a, b, c, d);
}

int IntervalPredicates::insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                                 const Point3& e) const {
  bool decided = false;
  const int s = interval_insphere(a, b, c, d, e, &decided);
  return decided ? s : exact_insphere(a, b, c, d, e);
}

}  // namespace dtlab
