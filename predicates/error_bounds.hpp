#pragma once
// The constants every floating-point filter of dtlab is built on, in one place:
// the unit roundoff, Dekker's splitter, Shewchuk's static error bounds for orient3d
// and insphere, and the range of magnitudes inside which those bounds hold.
//
// Notation: eps = 2^-53 (half an ulp of 1, the unit roundoff of round-to-nearest).
// A determinant evaluated in floating point with at most n roundings along any
// monomial errs by at most ((1+eps)^n - 1) * P, P the sum of the absolute values of
// its monomials (its permanent). The last addition never changes the sign (rounding
// is monotone and 0 is representable), so it costs a factor (1+eps), not a term eps.
//
// Users: predicates/adaptive.{hpp,cpp} (stages A..D), oracle/check/filtered_exact.cpp (the
// checker's float filter in front of GMP) and oracle/check/hull_degree.cpp (the cover
// proof's float filter). A new filter takes its bounds from here, with its own
// derivation next to its code when it needs a bound of its own.

namespace dtlab::error_bounds {

inline constexpr double kEps = 0x1p-53;            // unit roundoff
inline constexpr double kSplitter = 0x1p27 + 1.0;  // splits a double into two 26-bit halves

// Stage A (and any filter with the same evaluation order): orient3d has 7 roundings
// along a monomial, insphere 16 (one spare: 15 suffice). Stage B: the exact
// determinant of the rounded differences differs from the true one by the tails,
// ((1+eps)^k - 1) P for degree k (3 resp. 5), plus higher-order terms (Shewchuk 1997,
// section 4.3: same evaluation orders, same counts).
inline constexpr double kO3dA = (7.0 + 56.0 * kEps) * kEps;
inline constexpr double kO3dB = (3.0 + 28.0 * kEps) * kEps;
inline constexpr double kIspA = (16.0 + 224.0 * kEps) * kEps;
inline constexpr double kIspB = (5.0 + 72.0 * kEps) * kEps;
// Relative error of approximating the B expansion by its floating-point sum and of
// adding the correction term.
inline constexpr double kResult = (3.0 + 8.0 * kEps) * kEps;
// Stage C adds the first-order terms: for a multilinear determinant these are the
// determinants with one column replaced by its tails (and, for the lift column, by
// 2(x t_x + y t_y + z t_z)). Neglected second order: (1+eps)^k - 1 - k eps
// <= C(k,2) eps^2 (1+eps)^(k-2), i.e. 3 eps^2 P (orient3d) and 10 eps^2 P (insphere).
// Rounding of the correction, whose permanent is <= k eps P: orient3d 5 roundings
// in each of the three determinants plus 2 to add them: 7 * 3 eps^2 = 21 eps^2;
// insphere 11 (with the lift) plus 3 to add the four: 14 * 5 eps^2 = 70 eps^2.
// Totals 24 and 80 eps^2; the bounds round these up and leave generous room for
// third-order terms and the rounding of P itself.
inline constexpr double kO3dC = (32.0 + 1024.0 * kEps) * kEps * kEps;
inline constexpr double kIspC = (96.0 + 4096.0 * kEps) * kEps * kEps;

// The safe range. The bounds above assume that no operation underflows or overflows.
// With every non-zero input (a coordinate, or a coordinate difference) in
// [2^-140, 2^140], every value of a degree-k expression is a multiple of
// 2^(-192k) >= 2^-960 or zero (normal: the (1+eps) model and the error-free
// transformations hold), every product of up to five lies in [2^-700, 2^700], and
// Dekker's split does not overflow. Outside the range, filters defer to exact code
// (the libFuzzer target found mixed 1e294 / 1e-317 inputs that a filter without this
// guard signed wrongly).
inline constexpr double kSafeLow = 0x1p-140;
inline constexpr double kSafeHigh = 0x1p+140;

// True when v is zero or its magnitude lies in the safe range (false for NaN).
constexpr bool in_safe_range(double v) {
  const double m = v < 0 ? -v : v;
  return v == 0 || (m >= kSafeLow && m <= kSafeHigh);
}

}  // namespace dtlab::error_bounds
