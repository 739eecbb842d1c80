// Adaptive-precision predicates. This file is compiled with -ffp-contract=off:
// every error-free transformation below needs each + and * rounded on its own.
//
// Notation: eps = 2^-53 (half an ulp of 1, the unit roundoff of round-to-nearest),
// x~ the computed (rounded) coordinate difference, x = x~ + t its exact value, with
// |t| <= eps |x~|. A determinant evaluated in floating point with at most n
// roundings along any monomial has error <= ((1+eps)^n - 1) * P, P the sum of the
// absolute values of its monomials (its permanent). The last addition never changes
// the sign (rounding is monotone and 0 is representable), so it costs only a factor
// (1+eps) in the bound, not a term eps.
#include "predicates/adaptive.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

#include "predicates/error_bounds.hpp"
#include "predicates/exact.hpp"

namespace dtlab {
namespace {

using error_bounds::kEps;
using error_bounds::kSplitter;

// ---------------------------------------------------------------------------
// Error bounds: stages A..D need every nonzero coordinate in the safe range
// [2^-140, 2^140]; the bounds of stages A, B, C and of the result are Shewchuk's
// (same evaluation orders, same counts), derived in predicates/error_bounds.hpp.
using error_bounds::kIspA;
using error_bounds::kIspB;
using error_bounds::kIspC;
using error_bounds::kO3dA;
using error_bounds::kO3dB;
using error_bounds::kO3dC;
using error_bounds::kResult;

// ---------------------------------------------------------------------------
// Error-free transformations (paper, section 2). Valid without overflow/underflow.

inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

inline void fast_two_sum(double a, double b, double& x, double& y) {  // needs |a| >= |b|
  x = a + b;
  y = b - (x - a);
}

inline double two_diff_tail(double a, double b, double x) {  // x = fl(a - b)
  const double bv = a - x;
  const double av = x + bv;
  return (a - av) + (bv - b);
}

inline void split(double a, double& hi, double& lo) {
  const double c = kSplitter * a;
  hi = c - (c - a);
  lo = a - hi;
}

inline void two_product_presplit(double a, double b, double bhi, double blo, double& x,
                                 double& y) {
  x = a * b;
  double ahi, alo;
  split(a, ahi, alo);
  const double err1 = x - ahi * bhi;
  const double err2 = err1 - alo * bhi;
  const double err3 = err2 - ahi * blo;
  y = alo * blo - err3;
}

inline void two_product(double a, double b, double& x, double& y) {
  double bhi, blo;
  split(b, bhi, blo);
  two_product_presplit(a, b, bhi, blo, x, y);
}

// ---------------------------------------------------------------------------
// Expansions: arrays of nonoverlapping components, increasing magnitude, zeros
// eliminated (an expansion of the value 0 has one zero component).

// h = e + f (Fast-Expansion-Sum: merge by magnitude, then one pass of two-sums).
// h must have room for elen + flen components and may not alias e or f.
int expansion_sum(int elen, const double* e, int flen, const double* f, double* h) {
  // Merge into h first (by magnitude; written without branches, which would be
  // unpredictable), then accumulate in place: step m reads h[m] before writing
  // h[hlen] with hlen <= m - 1.
  int i = 0, j = 0, k = 0;
  while (i < elen && j < flen) {
    const bool take_e = std::fabs(e[i]) < std::fabs(f[j]);
    h[k++] = take_e ? e[i] : f[j];
    i += take_e;
    j += !take_e;
  }
  while (i < elen) h[k++] = e[i++];
  while (j < flen) h[k++] = f[j++];
  if (k == 1) return 1;
  int hlen = 0;
  double q, hh;
  fast_two_sum(h[1], h[0], q, hh);
  h[hlen] = hh;
  hlen += hh != 0;
  for (int m = 2; m < k; ++m) {
    const double g = h[m];
    two_sum(q, g, q, hh);
    h[hlen] = hh;
    hlen += hh != 0;
  }
  if (q != 0 || hlen == 0) h[hlen++] = q;
  return hlen;
}

// h = b * e (Scale-Expansion). h needs room for 2 * elen components.
int scale_expansion(int elen, const double* e, double b, double* h) {
  double bhi, blo;
  split(b, bhi, blo);
  double q, hh;
  int hlen = 0;
  two_product_presplit(e[0], b, bhi, blo, q, hh);
  h[hlen] = hh;
  hlen += hh != 0;
  for (int i = 1; i < elen; ++i) {
    double p1, p0, s;
    two_product_presplit(e[i], b, bhi, blo, p1, p0);
    two_sum(q, p0, s, hh);
    h[hlen] = hh;
    hlen += hh != 0;
    fast_two_sum(p1, s, q, hh);
    h[hlen] = hh;
    hlen += hh != 0;
  }
  if (q != 0 || hlen == 0) h[hlen++] = q;
  return hlen;
}

// h = e with fewer components (paper's Compress: a downward pass of fast two-sums
// gathering the value into few large components, then an upward pass). Exact; the
// result is nonoverlapping. h needs room for elen components and may not alias e.
int compress(int elen, const double* e, double* h) {
  int bottom = elen - 1;
  double q = e[bottom];
  for (int i = elen - 2; i >= 0; --i) {
    double qnew, small;
    fast_two_sum(q, e[i], qnew, small);
    if (small != 0) {
      h[bottom--] = qnew;
      q = small;
    } else {
      q = qnew;
    }
  }
  int top = 0;
  for (int i = bottom + 1; i < elen; ++i) {
    double qnew, small;
    fast_two_sum(h[i], q, qnew, small);
    if (small != 0) h[top++] = small;
    q = qnew;
  }
  h[top++] = q;
  return top;
}

double estimate(int len, const double* e) {
  double s = e[0];
  for (int i = 1; i < len; ++i) s += e[i];
  return s;
}

// Exact sign: the largest component dominates the rest.
int expansion_sign(int len, const double* e) { return sign_of(e[len - 1]); }

// Every coordinate an integer of magnitude below 2^51 (then every difference of two is
// exact). r + 2^52 rounds r < 2^51 to an integer (the spacing there is 1); subtracting
// 2^52 is exact, so the round trip returns r exactly when r is an integer.
bool integer_coordinates(std::initializer_list<const Point3*> pts) {
  auto integer = [](double v) {
    const double r = std::fabs(v);
    return r < 0x1p51 && (r + 0x1p52) - 0x1p52 == r;
  };
  for (const Point3* p : pts)
    if (!integer(p->x) || !integer(p->y) || !integer(p->z)) return false;
  return true;
}

// 2x2 minor p*q - s*t as an expansion of at most 4 components.
int minor2(double p, double q, double s, double t, double* h) {
  double x[2], y[2];
  two_product(p, q, x[1], x[0]);
  two_product(-s, t, y[1], y[0]);
  return expansion_sum(2, x, 2, y, h);
}

// Dynamic expansions for stage D (rare: only exactly or nearly degenerate input).
using Expansion = std::vector<double>;

Expansion exp_of(double hi, double lo) {
  if (lo == 0) return {hi};
  return {lo, hi};
}
Expansion compressed(const Expansion& e) {
  Expansion h(e.size());
  h.resize(compress(static_cast<int>(e.size()), e.data(), h.data()));
  return h;
}
Expansion operator+(const Expansion& e, const Expansion& f) {
  Expansion h(e.size() + f.size());
  h.resize(expansion_sum(static_cast<int>(e.size()), e.data(), static_cast<int>(f.size()),
                         f.data(), h.data()));
  return compressed(h);
}
Expansion operator-(const Expansion& e) {
  Expansion h(e);
  for (double& v : h) v = -v;
  return h;
}
Expansion operator-(const Expansion& e, const Expansion& f) { return e + (-f); }
Expansion operator*(const Expansion& e, const Expansion& f) {
  Expansion acc{0.0}, part(2 * e.size());
  for (double fj : f) {
    part.resize(2 * e.size());
    part.resize(scale_expansion(static_cast<int>(e.size()), e.data(), fj, part.data()));
    acc = acc + part;
  }
  return acc;
}
// Exact difference a - b as an expansion.
Expansion exact_diff(double a, double b) {
  const double x = a - b;
  return exp_of(x, two_diff_tail(a, b, x));
}

inline bool coord_ok(double v) { return error_bounds::in_safe_range(v); }
bool coords_ok(std::initializer_list<const Point3*> pts) {
  for (const Point3* p : pts)
    if (!coord_ok(p->x) || !coord_ok(p->y) || !coord_ok(p->z)) return false;
  return true;
}

inline int count(AdaptiveStats* s, bool insphere, AdaptiveStage st, int sign) {
  if (s) ++(insphere ? s->insphere : s->orient3d)[static_cast<int>(st)];
  return sign;
}


// Floating-point orient3d determinant of given differences (naive.hpp's formula).
inline double det3(double ax, double ay, double az, double bx, double by, double bz, double cx,
                   double cy, double cz) {
  return ax * (by * cz - bz * cy) + bx * (cy * az - cz * ay) + cx * (ay * bz - az * by);
}

// ---------------------------------------------------------------------------
// orient3d stages A..D (coordinates already known to be in the safe range).

}  // namespace

int adaptive_orient3d_stages(const Point3& a, const Point3& b, const Point3& c,
                                      const Point3& d, AdaptiveStats* stats) {
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  // A difference is computed as zero only when it is zero (subtraction never
  // underflows), so an all-zero column of differences means det = 0 exactly.
  if ((adx == 0 && bdx == 0 && cdx == 0) || (ady == 0 && bdy == 0 && cdy == 0) ||
      (adz == 0 && bdz == 0 && cdz == 0))
    return count(stats, false, AdaptiveStage::kZero, 0);
  if (!coords_ok({&a, &b, &c, &d}))
    return count(stats, false, AdaptiveStage::kExact, exact_orient3d(a, b, c, d));

  // A
  double det = det3(adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz);
  const double perm = std::fabs(adx) * (std::fabs(bdy * cdz) + std::fabs(bdz * cdy)) +
                      std::fabs(bdx) * (std::fabs(cdy * adz) + std::fabs(cdz * ady)) +
                      std::fabs(cdx) * (std::fabs(ady * bdz) + std::fabs(adz * bdy));
  double bound = kO3dA * perm;
  if (det > bound || -det > bound) return count(stats, false, AdaptiveStage::kA, sign_of(det));
  // Integer: with integer coordinates below 2^51 and every |difference| <= M = 2^16, det3
  // rounds nowhere: the differences are exact, 2x2 minors <= 2M^2, their products
  // <= 2M^3, the sums <= 6M^3 = 6 * 2^48 < 2^52, all integers, all representable.
  if (adaptive_detail::max3(std::fabs(adx), std::fabs(bdx), std::fabs(cdx)) <= 0x1p16 &&
      adaptive_detail::max3(std::fabs(ady), std::fabs(bdy), std::fabs(cdy)) <= 0x1p16 &&
      adaptive_detail::max3(std::fabs(adz), std::fabs(bdz), std::fabs(cdz)) <= 0x1p16 && integer_coordinates({&a, &b, &c, &d}))
    return count(stats, false, AdaptiveStage::kInteger, sign_of(det));

  // B: det of the rounded differences, exactly. Expand along the x column:
  // adx*(bdy cdz - bdz cdy) + bdx*(cdy adz - cdz ady) + cdx*(ady bdz - adz bdy).
  double m1[4], m2[4], m3[4], t1[8], t2[8], t3[8], t12[16], fin[24];
  const int l1 = minor2(bdy, cdz, bdz, cdy, m1);
  const int l2 = minor2(cdy, adz, cdz, ady, m2);
  const int l3 = minor2(ady, bdz, adz, bdy, m3);
  const int k1 = scale_expansion(l1, m1, adx, t1);
  const int k2 = scale_expansion(l2, m2, bdx, t2);
  const int k3 = scale_expansion(l3, m3, cdx, t3);
  const int k12 = expansion_sum(k1, t1, k2, t2, t12);
  const int kfin = expansion_sum(k12, t12, k3, t3, fin);
  det = estimate(kfin, fin);
  bound = kO3dB * perm;
  if (det >= bound || -det >= bound)
    return count(stats, false, AdaptiveStage::kB, expansion_sign(kfin, fin));

  // C
  const double adxt = two_diff_tail(a.x, d.x, adx), adyt = two_diff_tail(a.y, d.y, ady),
               adzt = two_diff_tail(a.z, d.z, adz), bdxt = two_diff_tail(b.x, d.x, bdx),
               bdyt = two_diff_tail(b.y, d.y, bdy), bdzt = two_diff_tail(b.z, d.z, bdz),
               cdxt = two_diff_tail(c.x, d.x, cdx), cdyt = two_diff_tail(c.y, d.y, cdy),
               cdzt = two_diff_tail(c.z, d.z, cdz);
  if (adxt == 0 && adyt == 0 && adzt == 0 && bdxt == 0 && bdyt == 0 && bdzt == 0 && cdxt == 0 &&
      cdyt == 0 && cdzt == 0)
    return count(stats, false, AdaptiveStage::kB, expansion_sign(kfin, fin));
  bound = kO3dC * perm + kResult * std::fabs(det);
  det += (det3(adxt, ady, adz, bdxt, bdy, bdz, cdxt, cdy, cdz) +
          det3(adx, adyt, adz, bdx, bdyt, bdz, cdx, cdyt, cdz)) +
         det3(adx, ady, adzt, bdx, bdy, bdzt, cdx, cdy, cdzt);
  if (det >= bound || -det >= bound) return count(stats, false, AdaptiveStage::kC, sign_of(det));

  // D: everything exactly.
  const Expansion ax = exact_diff(a.x, d.x), ay = exact_diff(a.y, d.y), az = exact_diff(a.z, d.z);
  const Expansion bx = exact_diff(b.x, d.x), by = exact_diff(b.y, d.y), bz = exact_diff(b.z, d.z);
  const Expansion cx = exact_diff(c.x, d.x), cy = exact_diff(c.y, d.y), cz = exact_diff(c.z, d.z);
  const Expansion full = ax * (by * cz - bz * cy) + bx * (cy * az - cz * ay) +
                         cx * (ay * bz - az * by);
  return count(stats, false, AdaptiveStage::kD,
               expansion_sign(static_cast<int>(full.size()), full.data()));
}

namespace {

// ---------------------------------------------------------------------------
// insphere

// Floating-point insphere determinant of given difference columns X, Y, Z and lift
// column L (rows a, b, c, d), with naive.hpp's evaluation order.
inline double det4(const double* X, const double* Y, const double* Z, const double* L) {
  const double ab = X[0] * Y[1] - X[1] * Y[0], bc = X[1] * Y[2] - X[2] * Y[1];
  const double cd = X[2] * Y[3] - X[3] * Y[2], da = X[3] * Y[0] - X[0] * Y[3];
  const double ac = X[0] * Y[2] - X[2] * Y[0], bd = X[1] * Y[3] - X[3] * Y[1];
  const double abc = Z[0] * bc - Z[1] * ac + Z[2] * ab;
  const double bcd = Z[1] * cd - Z[2] * bd + Z[3] * bc;
  const double cda = Z[2] * da + Z[3] * ac + Z[0] * cd;
  const double dab = Z[3] * ab + Z[0] * bd + Z[1] * da;
  return (L[3] * abc - L[2] * dab) + (L[1] * cda - L[0] * bcd);
}

// Insphere: when every coordinate of the five points is an integer of magnitude below
// 2^51 and every |difference| to e is at most M = 2^9, det4 and the lifts are computed
// without a single rounding: the differences are exact integers (|a - e| < 2^52), and
// every intermediate is an integer bounded by its own sum of |monomials|: lifts <= 3M^2,
// 2x2 minors <= 2M^2, 3x3 minors <= 6M^3, lift * minor <= 18M^5, the two partial sums
// <= 36M^5 and the result <= 72M^5 = 72 * 2^45 < 2^52, all representable. So `det` from
// stage A is the exact determinant.
bool small_integer_differences(std::initializer_list<const Point3*> pts, const double* aX, const double* aY,
                               const double* aZ) {
  for (int i = 0; i < 4; ++i)
    if (std::max(std::max(aX[i], aY[i]), aZ[i]) > 0x1p9) return false;
  return integer_coordinates(pts);
}

// Exact value of z-weighted 3x3 minor: z0*m0 - z1*m1 + z2*m2 (minors as expansions).
int minor3(double z0, int l0, const double* m0, double z1, int l1, const double* m1, double z2,
           int l2, const double* m2, double* h) {
  double t0[8], t1[8], t2[8], t01[16];
  const int k0 = scale_expansion(l0, m0, z0, t0);
  const int k1 = scale_expansion(l1, m1, -z1, t1);
  const int k2 = scale_expansion(l2, m2, z2, t2);
  const int k01 = expansion_sum(k0, t0, k1, t1, t01);
  double s[24];
  return compress(expansion_sum(k01, t01, k2, t2, s), s, h);
}

// h = (x^2 + y^2 + z^2) * m, exactly (m has <= 24 components, h room for 288): the
// lift as a compressed expansion first, then one scale of m per lift component.
int lift_times(double x, double y, double z, int len, const double* m, double* h) {
  double xx[2], yy[2], zz[2], s4[4], s6[6], lift[6];
  two_product(x, x, xx[1], xx[0]);
  two_product(y, y, yy[1], yy[0]);
  two_product(z, z, zz[1], zz[0]);
  const int k4 = expansion_sum(2, xx, 2, yy, s4);
  const int klift = compress(expansion_sum(k4, s4, 2, zz, s6), s6, lift);
  double acc[288], tmp[288], part[48];
  int alen = scale_expansion(len, m, lift[0], acc);
  for (int i = 1; i < klift; ++i) {
    const int plen = scale_expansion(len, m, lift[i], part);
    alen = expansion_sum(alen, acc, plen, part, tmp);
    std::copy(tmp, tmp + alen, acc);
  }
  return compress(alen, acc, h);
}

// Stage D of insphere: the determinant of the exact differences (expansions), for the
// inputs that stages A-C could not decide. Rare, so written for clarity, not speed.
int insphere_stage_d(const Point3* const p[4], const Point3& e) {
  Expansion ex[4], ey[4], ez[4], el[4];
  for (int i = 0; i < 4; ++i) {
    ex[i] = exact_diff(p[i]->x, e.x);
    ey[i] = exact_diff(p[i]->y, e.y);
    ez[i] = exact_diff(p[i]->z, e.z);
    el[i] = ex[i] * ex[i] + ey[i] * ey[i] + ez[i] * ez[i];
  }
  auto m2 = [&](int i, int j) { return ex[i] * ey[j] - ex[j] * ey[i]; };
  const Expansion eab = m2(0, 1), ebc = m2(1, 2), ecd = m2(2, 3), eda = m2(3, 0), eac = m2(0, 2), ebd = m2(1, 3);
  const Expansion eabc = ez[0] * ebc - ez[1] * eac + ez[2] * eab;
  const Expansion ebcd = ez[1] * ecd - ez[2] * ebd + ez[3] * ebc;
  const Expansion ecda = ez[2] * eda + ez[3] * eac + ez[0] * ecd;
  const Expansion edab = ez[3] * eab + ez[0] * ebd + ez[1] * eda;
  const Expansion full = (el[3] * eabc - el[2] * edab) + (el[1] * ecda - el[0] * ebcd);
  return expansion_sign(static_cast<int>(full.size()), full.data());
}

}  // namespace

int adaptive_insphere_stages(const Point3& a, const Point3& b, const Point3& c,
                                      const Point3& d, const Point3& e, AdaptiveStats* stats) {
  const Point3* p[4] = {&a, &b, &c, &d};
  double X[4], Y[4], Z[4], L[4];
  bool zx = true, zy = true, zz = true;
  for (int i = 0; i < 4; ++i) {
    X[i] = p[i]->x - e.x;
    Y[i] = p[i]->y - e.y;
    Z[i] = p[i]->z - e.z;
    zx = zx && X[i] == 0;
    zy = zy && Y[i] == 0;
    zz = zz && Z[i] == 0;
  }
  if (zx || zy || zz) return count(stats, true, AdaptiveStage::kZero, 0);  // a zero column
  if (!coords_ok({&a, &b, &c, &d, &e}))
    return count(stats, true, AdaptiveStage::kExact, exact_insphere(a, b, c, d, e));
  for (int i = 0; i < 4; ++i) L[i] = X[i] * X[i] + Y[i] * Y[i] + Z[i] * Z[i];

  // A. Permanent: the 4x4 determinant's monomials in absolute value.
  double det = det4(X, Y, Z, L);
  double aX[4], aY[4], aZ[4];
  for (int i = 0; i < 4; ++i) {
    aX[i] = std::fabs(X[i]);
    aY[i] = std::fabs(Y[i]);
    aZ[i] = std::fabs(Z[i]);
  }
  const double pab = aX[0] * aY[1] + aX[1] * aY[0], pbc = aX[1] * aY[2] + aX[2] * aY[1];
  const double pcd = aX[2] * aY[3] + aX[3] * aY[2], pda = aX[3] * aY[0] + aX[0] * aY[3];
  const double pac = aX[0] * aY[2] + aX[2] * aY[0], pbd = aX[1] * aY[3] + aX[3] * aY[1];
  const double pabc = aZ[0] * pbc + aZ[1] * pac + aZ[2] * pab;
  const double pbcd = aZ[1] * pcd + aZ[2] * pbd + aZ[3] * pbc;
  const double pcda = aZ[2] * pda + aZ[3] * pac + aZ[0] * pcd;
  const double pdab = aZ[3] * pab + aZ[0] * pbd + aZ[1] * pda;
  const double perm = (L[3] * pabc + L[2] * pdab) + (L[1] * pcda + L[0] * pbcd);
  double bound = kIspA * perm;
  if (det > bound || -det > bound) return count(stats, true, AdaptiveStage::kA, sign_of(det));

  // Integer: lattices and integer-sampled spheres, where insphere is often exactly 0,
  // would otherwise pay stage B's expansions on every tie.
  if (small_integer_differences({&a, &b, &c, &d, &e}, aX, aY, aZ))
    return count(stats, true, AdaptiveStage::kInteger, sign_of(det));

  // B: exact determinant of the rounded differences.
  double ab[4], bc[4], cd[4], da[4], ac[4], bd[4];
  const int lab = minor2(X[0], Y[1], X[1], Y[0], ab), lbc = minor2(X[1], Y[2], X[2], Y[1], bc);
  const int lcd = minor2(X[2], Y[3], X[3], Y[2], cd), lda = minor2(X[3], Y[0], X[0], Y[3], da);
  const int lac = minor2(X[0], Y[2], X[2], Y[0], ac), lbd = minor2(X[1], Y[3], X[3], Y[1], bd);
  double abc[24], bcd[24], cda[24], dab[24];
  // cda = z2*da + z3*ac + z0*cd and dab = z3*ab + z0*bd + z1*da: written with the
  // "minus" slot fed the negated coefficient.
  const int labc = minor3(Z[0], lbc, bc, Z[1], lac, ac, Z[2], lab, ab, abc);
  const int lbcd = minor3(Z[1], lcd, cd, Z[2], lbd, bd, Z[3], lbc, bc, bcd);
  const int lcda = minor3(Z[2], lda, da, -Z[3], lac, ac, Z[0], lcd, cd, cda);
  const int ldab = minor3(Z[3], lab, ab, -Z[0], lbd, bd, Z[1], lda, da, dab);
  double dterm[288], cterm[288], bterm[288], aterm[288], s1[576], s2[576], fin[1152];
  // Lift of a row times its cofactor; signs: +d*abc - c*dab + b*cda - a*bcd.
  const int kd = lift_times(X[3], Y[3], Z[3], labc, abc, dterm);
  for (int i = 0; i < ldab; ++i) dab[i] = -dab[i];
  const int kc = lift_times(X[2], Y[2], Z[2], ldab, dab, cterm);
  const int kb = lift_times(X[1], Y[1], Z[1], lcda, cda, bterm);
  for (int i = 0; i < lbcd; ++i) bcd[i] = -bcd[i];
  const int ka = lift_times(X[0], Y[0], Z[0], lbcd, bcd, aterm);
  const int k1 = expansion_sum(kd, dterm, kc, cterm, s1);
  const int k2 = expansion_sum(kb, bterm, ka, aterm, s2);
  const int kfin = expansion_sum(k1, s1, k2, s2, fin);
  det = estimate(kfin, fin);
  bound = kIspB * perm;
  if (det >= bound || -det >= bound)
    return count(stats, true, AdaptiveStage::kB, expansion_sign(kfin, fin));

  // C
  double Xt[4], Yt[4], Zt[4], Lt[4];
  bool all_zero = true;
  for (int i = 0; i < 4; ++i) {
    Xt[i] = two_diff_tail(p[i]->x, e.x, X[i]);
    Yt[i] = two_diff_tail(p[i]->y, e.y, Y[i]);
    Zt[i] = two_diff_tail(p[i]->z, e.z, Z[i]);
    all_zero = all_zero && Xt[i] == 0 && Yt[i] == 0 && Zt[i] == 0;
    Lt[i] = 2 * (X[i] * Xt[i] + Y[i] * Yt[i] + Z[i] * Zt[i]);
  }
  if (all_zero) return count(stats, true, AdaptiveStage::kB, expansion_sign(kfin, fin));
  bound = kIspC * perm + kResult * std::fabs(det);
  det += ((det4(Xt, Y, Z, L) + det4(X, Yt, Z, L)) + det4(X, Y, Zt, L)) + det4(X, Y, Z, Lt);
  if (det >= bound || -det >= bound) return count(stats, true, AdaptiveStage::kC, sign_of(det));

  // D: everything exactly.
  return count(stats, true, AdaptiveStage::kD, insphere_stage_d(p, e));
}

}  // namespace dtlab
