#pragma once
// Shewchuk's adaptive-precision orient3d and insphere ("Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997), written
// from the paper, behind a semi-static filter and in front of an exact fallback.
//
// Pipeline of one call (details and error-bound derivations in adaptive.cpp):
//   semi-static: the naive determinant against a bound from the largest
//                coordinate differences (orient3d) or the largest lift (insphere)
//                (cheapest; valid when those lie in a safe range)
//   A: the naive determinant against a bound from its permanent
//   integer: integer coordinates below 2^51 with small differences: the naive
//            determinant is exact
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
#include "predicates/error_bounds.hpp"
#include "predicates/naive.hpp"
#include "predicates/sign.hpp"

namespace dtlab {

// Which step of the pipeline decided a call. kZero: a column of the matrix of
// differences is exactly zero (all points share a coordinate), so the answer is 0.
// kInteger: small integer coordinates, where stage A's double evaluation is exact
// (bounds in adaptive.cpp).
enum class AdaptiveStage : int { kZero, kSemiStatic, kA, kInteger, kB, kC, kD, kExact, kCount };

constexpr std::array<std::string_view, static_cast<int>(AdaptiveStage::kCount)>
    kAdaptiveStageNames = {"zero", "semistatic", "A", "integer", "B", "C", "D", "exact"};

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

using error_bounds::kEps;  // unit roundoff of round-to-nearest
// Semi-static orient3d: det = adx*(bdy*cdz - bdz*cdy) + ... (naive.hpp's formula).
// Along a monomial: 3 rounded differences, the minor's product and subtraction, the
// outer product, two additions of which the last is free (rounding is monotone and 0
// is representable, so the last rounding cannot change the sign; it costs a factor
// 1+eps): 7 roundings, error <= 7 eps (1 + 4 eps) sum|monomials|. Each of the six
// monomials takes one x, one y and one z difference: sum|monomials| <= 6 mx my mz
// (m = largest |rounded difference| per axis). 42 eps, rounded up to 43 eps to cover
// the three roundings of the bound itself, the free last addition and underflow.
inline constexpr double kO3dSemiStatic = 43 * kEps;
// Safe range of orient3d's largest differences. Overflow: values stay below 6 * 2^600.
// Underflow: an underflowing product or fma errs by at most 2^-1075 in absolute terms,
// then meets at most 1 further factor <= 2^200 and a few additions: extra error
// < 2^-860, while the bound is >= 2^-648 and has a relative slack of 1/43 over the
// rounding error: the extra error fits in it.
inline constexpr double kO3dLow = 0x1p-200, kO3dHigh = 0x1p200;
// Semi-static insphere, from the largest lift L = max(alift, blift, clift, dlift)
// (already computed, so the filter costs 3 max, 5 products and 2 comparisons).
// Roundings along a monomial x_i y_j z_k w_l^2 (72 of them): 5 rounded differences,
// the 2x2 minor (2), the 3x3 minor (product + 2 additions), the lift (square + 2
// additions), lift times minor (1), the final additions (2, the last is free: rounding
// is monotone and 0 is representable, so it cannot change the sign; it costs a factor
// 1+eps): 15, so |det - D| <= gamma_15 S, gamma_15 = 15 eps / (1 - 15 eps), with S the
// sum of |monomials| in the exact differences. S = sum_l lift_l perm|M_l|, M_l the 3x3
// matrix of the other three points' differences; perm|M| <= prod of its row 1-norms
// <= prod sqrt(3 lift_row), so S <= 4 * 3^1.5 * L^2.5 = 20.785 L^2.5 (exact lifts).
// The computed L has 5 roundings from the exact lifts (2 in the rounded differences,
// 3 in the lift): exact L <= L / (1 - eps)^5. Hence |error| <= 311.78 eps (1 + 30 eps)
// L^2.5, and with the free last addition the test |det| > 320 eps L^2.5 is safe with
// a slack of 8 eps L^2.5. It is evaluated squared: det^2 > (320 eps)^2 L^5, where
// (320 eps)^2 = 102400 * 2^-106 is exact, the 4 roundings of the bound and the one of
// det^2 cost a factor (1 - eps)^2 / sqrt(1 + eps) on 320 eps: inside the slack.
// Range: only L >= 2^-180 is needed. Then the bound (>= 2^-989) is a normal number, a
// det^2 that underflows fails the test, and an underflowing product (absolute error
// <= 2^-1075, then multiplied by at most 6 (3L)^1.5) adds < 2^-560 eps L^2.5: inside
// the slack. No upper limit: every intermediate of det is below 72 max(1, L)^2.5
// (1 + tiny), so if any of them overflows, L^5 overflows too and the bound is
// infinite: the test is false (also for a NaN det). A det^2 overflowing on its own
// (|det| > 2^512, no intermediate overflowed) correctly passes.
inline constexpr double kIspSemiStaticSquared = (320 * kEps) * (320 * kEps);
inline constexpr double kIspLiftLow = 0x1p-180;

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
  // naive.hpp's evaluation order (the bound above counts its roundings).
  const InsphereEval v = insphere_eval(a, b, c, d, e);
  const double det = v.det, lift = v.max_lift;
  const double lift2 = lift * lift;
  const double bound = kIspSemiStaticSquared * (lift2 * lift2 * lift);
  if ((lift >= kIspLiftLow) & (det * det > bound))
    return counted(stats, true, AdaptiveStage::kSemiStatic, det > 0 ? 1 : -1);
  return adaptive_insphere_stages(a, b, c, d, e, stats);
}

// The insphere filter of adaptive_insphere, fused with the orientation tests a flip
// classification asks next. It evaluates insphere(a,b,c,d,e) once and returns the
// signs that semi-static bounds decide, FilterSign::undecided for the others (the caller then
// asks the full predicates):
//   insphere  as adaptive_insphere's filter;
//   side[k]   orient3d(a,b,c,d with its k-th point replaced by e): insphere_eval's
//             minor[k]. Each minor has orient3d_value's rounding count along every
//             monomial (3 differences, a 2x2 minor, a product, two additions), so the
//             orient3d bound above holds: error <= 43 eps mx my mz over its rows'
//             rounded differences. Each rounded difference is at most sqrt of the
//             exact lift of its row's rounded differences, which exceeds the computed
//             L by at most a factor (1 - eps)^-3 (a square and two additions):
//             mx my mz <= L^1.5 (1 - eps)^-4.5. The test |minor| > 44 eps L^1.5 is
//             therefore safe, with a relative slack of 1/43 for the roundings of the
//             test itself, evaluated squared: minor^2 > (44 eps)^2 L^3 (5 roundings).
//             Range: L >= 2^-180 as for insphere; then an underflowing product errs by
//             <= 2^-1075 times at most a factor sqrt(L), far inside the slack. If L^3
//             overflows the test is false; a NaN minor fails it; a minor^2 overflowing
//             alone means |minor| > 2^512 > L^1.5: correctly decided.
struct InsphereSides {
  FilterSign insphere;
  FilterSign side[4];
};

namespace adaptive_detail {
inline constexpr double kSideSemiStaticSquared = (44 * kEps) * (44 * kEps);
}  // namespace adaptive_detail

inline InsphereSides adaptive_insphere_sides(const Point3& a, const Point3& b, const Point3& c,
                                             const Point3& d, const Point3& e, AdaptiveStats* stats) {
  using namespace adaptive_detail;
  const InsphereEval v = insphere_eval(a, b, c, d, e);
  constexpr FilterSign u = FilterSign::undecided;
  InsphereSides r{u, {u, u, u, u}};
  if (!(v.max_lift >= kIspLiftLow)) return r;
  const double lift2 = v.max_lift * v.max_lift;
  if (v.det * v.det > kIspSemiStaticSquared * (lift2 * lift2 * v.max_lift))
    r.insphere = filter_sign(counted(stats, true, AdaptiveStage::kSemiStatic, v.det > 0 ? 1 : -1));
  const double side_bound = kSideSemiStaticSquared * (lift2 * v.max_lift);
  for (int k = 0; k < 4; ++k)
    if (v.minor[k] * v.minor[k] > side_bound) r.side[k] = filter_sign(v.minor[k]);
  return r;
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
  InsphereSides insphere_sides(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                               const Point3& e) const {
    return adaptive_insphere_sides(a, b, c, d, e, stats);
  }
};

static_assert(PredicateBackend<AdaptivePredicates>);

}  // namespace dtlab
