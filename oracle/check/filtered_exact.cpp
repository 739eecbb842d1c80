#include "oracle/check/filtered_exact.hpp"

#include <cmath>
#include <initializer_list>

#include "predicates/error_bounds.hpp"
#include "predicates/exact.hpp"

namespace dtlab {
namespace {

// Shewchuk's stage-A bounds: the evaluation orders below are naive.hpp's.
constexpr double kO3dBound = error_bounds::kO3dA;
constexpr double kInsBound = error_bounds::kIspA;
// Outside [kTiny, kHuge] intermediate products may underflow or overflow.
constexpr double kTiny = 0x1p-900;
constexpr double kHuge = 0x1p+900;

// Shewchuk's bounds also assume that no product underflows: with every non-zero
// difference in the safe range (predicates/error_bounds.hpp) none does; outside it
// the exact code answers. The same test as error_bounds::in_safe_range on each value
// (false for NaN), accumulated without a branch per value: the values are nearly
// always all in range, and one test at the end replaces twelve branches.
bool in_safe_range(std::initializer_list<double> diffs) {
  int outside = 0;
  for (double v : diffs) {
    const double m = std::fabs(v);
    outside |= int(!(m <= error_bounds::kSafeHigh)) | (int(m < error_bounds::kSafeLow) & int(m != 0));
  }
  return outside == 0;
}

bool trusted(double det, double permanent, double bound) {
  if (!(permanent >= kTiny && permanent <= kHuge)) return false;  // also catches NaN
  return std::fabs(det) > bound * permanent;
}

}  // namespace

int FilteredExact::orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  if (in_safe_range({adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz}) && trusted(det, permanent, kO3dBound))
    return det > 0 ? 1 : -1;
  return exact_orient3d(a, b, c, d);
}

int FilteredExact::insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) const {
  const double aex = a.x - e.x, bex = b.x - e.x, cex = c.x - e.x, dex = d.x - e.x;
  const double aey = a.y - e.y, bey = b.y - e.y, cey = c.y - e.y, dey = d.y - e.y;
  const double aez = a.z - e.z, bez = b.z - e.z, cez = c.z - e.z, dez = d.z - e.z;
  const double aexbey = aex * bey, bexaey = bex * aey;
  const double bexcey = bex * cey, cexbey = cex * bey;
  const double cexdey = cex * dey, dexcey = dex * cey;
  const double dexaey = dex * aey, aexdey = aex * dey;
  const double aexcey = aex * cey, cexaey = cex * aey;
  const double bexdey = bex * dey, dexbey = dex * bey;
  const double ab = aexbey - bexaey, bc = bexcey - cexbey, cd = cexdey - dexcey;
  const double da = dexaey - aexdey, ac = aexcey - cexaey, bd = bexdey - dexbey;
  const double abc = aez * bc - bez * ac + cez * ab;
  const double bcd = bez * cd - cez * bd + dez * bc;
  const double cda = cez * da + dez * ac + aez * cd;
  const double dab = dez * ab + aez * bd + bez * da;
  const double alift = aex * aex + aey * aey + aez * aez;
  const double blift = bex * bex + bey * bey + bez * bez;
  const double clift = cex * cex + cey * cey + cez * cez;
  const double dlift = dex * dex + dey * dey + dez * dez;
  const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  using std::fabs;
  const double ab_ = fabs(aexbey) + fabs(bexaey), bc_ = fabs(bexcey) + fabs(cexbey);
  const double cd_ = fabs(cexdey) + fabs(dexcey), da_ = fabs(dexaey) + fabs(aexdey);
  const double ac_ = fabs(aexcey) + fabs(cexaey), bd_ = fabs(bexdey) + fabs(dexbey);
  const double permanent = (cd_ * fabs(bez) + bd_ * fabs(cez) + bc_ * fabs(dez)) * alift +
                           (da_ * fabs(cez) + ac_ * fabs(dez) + cd_ * fabs(aez)) * blift +
                           (ab_ * fabs(dez) + bd_ * fabs(aez) + da_ * fabs(bez)) * clift +
                           (bc_ * fabs(aez) + ac_ * fabs(bez) + ab_ * fabs(cez)) * dlift;
  if (in_safe_range({aex, aey, aez, bex, bey, bez, cex, cey, cez, dex, dey, dez}) && trusted(det, permanent, kInsBound))
    return det > 0 ? 1 : -1;
  return exact_insphere(a, b, c, d, e);
}

}  // namespace dtlab
