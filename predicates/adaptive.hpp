#pragma once
// Shewchuk's adaptive-precision orient3d and insphere ("Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997), written
// from the paper, behind a semi-static filter and in front of an exact fallback.
//
// Pipeline of one call (details and error-bound derivations in adaptive.cpp):
//   semi-static: the naive determinant against a bound from the largest
//                coordinate differences (cheapest; valid when those lie in a safe range)
//   A: the naive determinant against a bound from its permanent
//   B: the exact determinant of the rounded differences (expansion arithmetic)
//   C: B plus the first-order effect of the differences' roundoff tails
//   D: the exact determinant (expansion arithmetic)
//   exact: GMP (ExactPredicates), taken when some nonzero coordinate lies outside
//          [2^-140, 2^140], where A..D could underflow or overflow.
// The answer is the exact sign for every finite input.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "predicates/backend.hpp"

namespace dtlab {

// Which step of the pipeline decided a call. kZero: a column of the matrix of
// differences is exactly zero (all points share a coordinate), so the answer is 0.
enum class AdaptiveStage : int { kZero, kSemiStatic, kA, kB, kC, kD, kExact, kCount };

constexpr std::array<std::string_view, static_cast<int>(AdaptiveStage::kCount)>
    kAdaptiveStageNames = {"zero", "semistatic", "A", "B", "C", "D", "exact"};

struct AdaptiveStats {
  std::array<std::uint64_t, static_cast<int>(AdaptiveStage::kCount)> orient3d{};
  std::array<std::uint64_t, static_cast<int>(AdaptiveStage::kCount)> insphere{};
};

// Stages A..D and the exact fallback (adaptive.cpp, compiled without FMA contraction).
int adaptive_orient3d_stages(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                             AdaptiveStats* stats);
int adaptive_insphere_stages(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                             const Point3& e, AdaptiveStats* stats);

// The semi-static filters are inline: they use no error-free transformation, so they
// stay correct if the including file lets the compiler fuse a*b+c (an FMA only
// removes roundings from the count below). Never compile with -ffast-math.
namespace adaptive_detail {

inline constexpr double kEps = 0x1p-53;  // unit roundoff of round-to-nearest
// Semi-static orient3d: det = adx*(bdy*cdz - bdz*cdy) + ... (naive.hpp's formula).
// Along a monomial: 3 rounded differences, the minor's product and subtraction, the
// outer product, two additions of which the last is free (rounding is monotone and 0
// is representable, so the last rounding cannot change the sign; it costs a factor
// 1+eps): 7 roundings, error <= 7 eps (1 + 4 eps) sum|monomials|. Each of the six
// monomials takes one x, one y and one z difference: sum|monomials| <= 6 mx my mz
// (m = largest |rounded difference| per axis). 42 eps, rounded up to 43 eps to cover
// the three roundings of the bound itself, the free last addition and underflow.
inline constexpr double kO3dSemiStatic = 43 * kEps;
// Semi-static insphere: monomials x_i y_j z_k w_l^2 (w in x,y,z; 72 of them) see
// 5 rounded differences, the 2x2 minor (2), the 3x3 minor (product + 2 additions),
// the lift (square + 2 additions), lift times minor (1), the final additions (1, the
// last is free): 15 roundings. sum|monomials| <= 24 mx my mz (mx^2 + my^2 + mz^2),
// hence 360 eps (1 + 8 eps); 361 eps covers computing the bound and underflow.
inline constexpr double kIspSemiStatic = 361 * kEps;
// Safe ranges for the largest differences. Overflow: orient3d values stay below
// 6 * 2^600, insphere below 72 * 2^500. Underflow: an underflowing product or fma errs
// by at most 2^-1075 in absolute terms, then meets at most 1 (orient3d) or 4
// (insphere) further factors <= 2^200 resp. 2^100 and a few additions: extra error
// < 2^-860 resp. 2^-660, while the bound is >= 2^-648 resp. 2^-545 and has a relative
// slack of 1/43 resp. 1/361 over the rounding error: the extra error fits in it.
inline constexpr double kO3dLow = 0x1p-200, kO3dHigh = 0x1p200;
inline constexpr double kIspLow = 0x1p-100, kIspHigh = 0x1p100;

inline int counted(AdaptiveStats* s, bool insphere, AdaptiveStage st, int sign) {
  if (s) ++(insphere ? s->insphere : s->orient3d)[static_cast<int>(st)];
  return sign;
}
inline double abs(double v) { return std::fabs(v); }
inline double max3(double a, double b, double c) { return std::max(std::max(a, b), c); }

}  // namespace adaptive_detail

inline int adaptive_orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                             AdaptiveStats* stats) {
  using namespace adaptive_detail;
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  const double det =
      adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) + cdx * (ady * bdz - adz * bdy);
  const double mx = max3(abs(adx), abs(bdx), abs(cdx));
  const double my = max3(abs(ady), abs(bdy), abs(cdy));
  const double mz = max3(abs(adz), abs(bdz), abs(cdz));
  if (std::min(std::min(mx, my), mz) >= kO3dLow && std::max(std::max(mx, my), mz) <= kO3dHigh) {
    const double bound = kO3dSemiStatic * (mx * my * mz);
    if (std::fabs(det) > bound)  // false for NaN: overflow goes on to the slow path
      return counted(stats, false, AdaptiveStage::kSemiStatic, det > 0 ? 1 : -1);
  }
  return adaptive_orient3d_stages(a, b, c, d, stats);
}

inline int adaptive_insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                             const Point3& e, AdaptiveStats* stats) {
  using namespace adaptive_detail;
  const double aex = a.x - e.x, aey = a.y - e.y, aez = a.z - e.z;
  const double bex = b.x - e.x, bey = b.y - e.y, bez = b.z - e.z;
  const double cex = c.x - e.x, cey = c.y - e.y, cez = c.z - e.z;
  const double dex = d.x - e.x, dey = d.y - e.y, dez = d.z - e.z;
  // naive.hpp's evaluation order (the bound above counts its roundings).
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
  const double mx = max3(max3(abs(aex), abs(bex), abs(cex)), abs(dex), 0.0);
  const double my = max3(max3(abs(aey), abs(bey), abs(cey)), abs(dey), 0.0);
  const double mz = max3(max3(abs(aez), abs(bez), abs(cez)), abs(dez), 0.0);
  if (std::min(std::min(mx, my), mz) >= kIspLow && std::max(std::max(mx, my), mz) <= kIspHigh) {
    const double bound = kIspSemiStatic * ((mx * my) * mz) * ((mx * mx + my * my) + mz * mz);
    if (std::fabs(det) > bound)
      return counted(stats, true, AdaptiveStage::kSemiStatic, det > 0 ? 1 : -1);
  }
  return adaptive_insphere_stages(a, b, c, d, e, stats);
}

struct AdaptivePredicates {
  // Optional: when set, each call counts the stage that decided it (the Counting
  // wrapper sets it). Not thread-safe; give each thread its own.
  AdaptiveStats* stats = nullptr;

  static constexpr std::string_view name() { return "adaptive"; }
  int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    return adaptive_orient3d(a, b, c, d, stats);
  }
  int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
               const Point3& e) const {
    return adaptive_insphere(a, b, c, d, e, stats);
  }
};

static_assert(PredicateBackend<AdaptivePredicates>);

}  // namespace dtlab
