#include "voronoi_check/vertex_filter.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "kernel/cpu_features.hpp"

// Compiled with -ffp-contract=off (CMakeLists.txt; and -fno-trapping-math, which only lets
// BoundBatch's comparisons run on vectors): the counts below assume one
// rounding per + - * / sqrt, no fused multiply-add.
//
// The bound (Shewchuk-style a-priori counts, u = 2^-53, u_L = 2^-64 for long double;
// gamma_k = k u / (1 - k u) bounds k relative roundings of one product term; Higham,
// "Accuracy and Stability of Numerical Algorithms", lemma 3.1). Exact quantities are
// written plain, computed ones with ~.
//
// Planes. Bisector: n_k = q_k - s_k (1 rounding), c = ((n0 n0 + n1 n1) + n2 n2) / 2
// (each product term: 2 from its n's, 1 product, at most 2 sums: 5; /2 is exact in
// range). Wall: n = e_k exact, c = w - s_k (1 rounding). So every n component carries
// at most 1 rounding, every c at most 5, as product terms of the exact inputs.
// The norm m~ = sqrt(n~ . n~) (5 + 1 roundings): ||n|| <= m~ (1 + 4u).
//
// Determinant D = a . (b x d): a_j (1) times (b_y d_z - b_z d_y) (2 + 1 + 1 = 4) is 1
// product more (6), the sum of three 2 more: 8 roundings, so
//   |D~ - D| <= gamma_8 P_D,  P_D = sum_j |a_j| (|b_y d_z| + |b_z d_y|)  (the permanent),
// and with P_D <= P~_D (1 + 12 u) (the permanent of the rounded inputs, computed):
// E_D = 9 u P~_D (8 u (1 + 8 u) (1 + 12 u) < 9 u, the product's own rounding included).
//
// Numerator N_j = c_a (b x d)_j + c_b (d x a)_j + c_d (a x b)_j (Cramer's rule, as the
// long double path): 5 (c) + 4 (cross) + 1 (product) + 2 (sums) = 12 roundings:
//   |N~_j - N_j| <= gamma_12 P_N,j,  P_N,j = |c_a| |b x d|_j + |c_b| |d x a|_j + |c_d| |a x b|_j
// (|b x d|_j: the cross product's two terms in absolute value); with |c| <= |c~| (1 +
// gamma_5), the n's factors and the permanent's own roundings, E_N = 13 u P~_N,j
// (12 u (1 + 40 u) < 13 u).
//
// Solution x_j = N_j / D. Required: E_D <= 2^-10 |D~| (else no verdict). With r_j =
// N~_j / D~: |x_j - r_j| <= (E_N + |r_j| E_D) / (|D~| - E_D). One division for the
// three: x~_j = fl(N~_j fl(1 / D~)) is two roundings from r_j (|x~_j - r_j| <= 2.01 u
// |x~_j|), and the bound's own products by fl(1 / |D~|) lose a few u, inside the 1.01
// that already covers 1 / (1 - 2^-10), so
//   |x~_j - x_j| <= X_j = 1.01 (E_N + |x~_j| E_D) / |D~| + 2.02 u |x~_j|.
// Distance: t_j = p_j - s_j (1 rounding), e_j = t_j - x_j (1 rounding), d = max |e_j|:
//   |e~_j - e_j| <= B_j = X_j + 1.01 u (|t~_j| + |e~_j|),   |d~ - d| <= B = max_j B_j.
//
// The long double path computes the same expressions with at most the same rounding
// counts (its n = L(q) - L(s) has at most 1; it divides three times, one rounding each),
// so its distance d_L obeys the same bound with
// u_L: |d_L - d| <= 2^-11 (1 + 2^-9) B < B / 1024 (its magnitudes lie within 2^-9 of
// these, by the conditioning requirement). Hence d_L <= d~ + B (1 + 2^-10) and the
// returned U = fl(fl(d~ (1 + 4u)) + fl(1.01 B)) is above it: the three roundings lose
// at most u (d~ (1 + 5u) + 1.02 B) + 1.01 u B, less than the 3u d~ + 0.008 B spared.
// The long double distance is then rounded to double, which is monotone:
// double(d_L) <= U whenever U is a double above d_L.
//
// Decided: the long double path takes the triple when |D_L| / (N_a N_b N_d) > 1e-9
// (its own norms). |D_L| >= |D~| - E_D (1 + 2^-10) and N <= m~ (1 + 8 u), so
// |D~| - E_D > 2e-9 m~_a m~_b m~_d certifies it with a factor of 2 to spare.
//
// Range: the counts hold without underflow or overflow. Each plane needs
// 2^-1000 <= n~ . n~ <= 2^1000 (bisectors; walls have n . n = 1) and a finite c~; each
// triple m~_a m~_b m~_d in [2^-900, 2^900] and every P~_N,j <= 2^900: no intermediate
// overflows; |D~| <= P~_D (1 + 12u) <= 2^900 (1 + 13u), so fl(1 / D~) >= 2^-901 does not
// underflow. |D~| >= 2^-1000 is required (the decided test asks far more, |D~| >
// 2^-929; tet_spheres.cpp asks only this): then P~_D > 2^-1001, and an underflowed term,
// at most 2^-1074 absolute, about 2^-1068 in all, is far inside u P~_D and inside the
// u 2^-900 that E_N adds by taking max(P~_N,j, 2^-900). Non-finite vertices or results
// give no bound: the long double path then decides.

namespace dtlab {

using namespace vor;

bool filter_plane(std::int32_t tag, std::span<const Point3> sites, const Point3& s, const Box& box, FilterPlane& out) {
  if (tag >= 0) {
    if (static_cast<std::size_t>(tag) >= sites.size()) return false;
    bisector_plane(sites[tag], s, out);
    return true;
  }
  if (tag < -6) return false;
  const int axis = (-tag - 1) / 2;
  const bool hi = (-tag - 1) % 2;
  const double lo_c[3] = {box.lo.x, box.lo.y, box.lo.z}, hi_c[3] = {box.hi.x, box.hi.y, box.hi.z};
  const double sc[3] = {s.x, s.y, s.z};
  out.n[0] = out.n[1] = out.n[2] = 0;
  out.n[axis] = 1;
  out.c = (hi ? hi_c[axis] : lo_c[axis]) - sc[axis];
  out.ok = std::isfinite(out.c);
  out.norm = out.ok ? 1 : NAN;
  return true;
}

void filter_planes(std::span<const std::int32_t> tags, std::span<const Point3> sites, const Point3& site,
                   const Box& box, FilterPlane* out, char* found) {
  for (std::size_t f = 0; f < tags.size(); ++f) found[f] = filter_plane(tags[f], sites, site, box, out[f]);
}

namespace {

[[gnu::always_inline]] inline void cross(const double* a, const double* b, double* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// |a_1 b_2| + |a_2 b_1|, ...: the cross product's terms in absolute value.
[[gnu::always_inline]] inline void abs_cross(const double* a, const double* b, double* out) {
  out[0] = std::abs(a[1] * b[2]) + std::abs(a[2] * b[1]);
  out[1] = std::abs(a[2] * b[0]) + std::abs(a[0] * b[2]);
  out[2] = std::abs(a[0] * b[1]) + std::abs(a[1] * b[0]);
}

// The bound's arithmetic for one lane, without a branch (every condition of the
// derivation folded into `ok`), so that BoundBatch's loop runs it on several lanes per
// instruction: the same operations in the same order whatever the width. Reads fields
// 0-12 of `in` (the planes).
[[gnu::always_inline]] inline bool meet_lane(const BoundInputs& in, PlanesMeet& out) {
  constexpr double u = 0x1p-53;
  const double *a = in.f, *b = in.f + 3, *d = in.f + 6;
  const double in_ca = in.f[9], in_cb = in.f[10], in_cd = in.f[11];
  out.norms = in.f[12];
  bool ok = (out.norms >= 0x1p-900) & (out.norms <= 0x1p900);
  double bd[3], da[3], ab[3], pbd[3], pda[3], pab[3];
  cross(b, d, bd);
  abs_cross(b, d, pbd);
  const double det = a[0] * bd[0] + a[1] * bd[1] + a[2] * bd[2];
  const double p_d = std::abs(a[0]) * pbd[0] + std::abs(a[1]) * pbd[1] + std::abs(a[2]) * pbd[2];
  out.det = std::abs(det), out.det_error = 9 * u * p_d;
  ok &= (out.det >= 0x1p-1000) & (out.det_error <= 0x1p-10 * out.det);
  cross(d, a, da);
  cross(a, b, ab);
  abs_cross(d, a, pda);
  abs_cross(a, b, pab);
  const double ca = std::abs(in_ca), cb = std::abs(in_cb), cd = std::abs(in_cd);
  const double inv = 1 / det, inv_abs = std::abs(inv);
  for (int j = 0; j < 3; ++j) {
    const double p_n = ca * pbd[j] + cb * pda[j] + cd * pab[j];
    ok &= p_n <= 0x1p900;
    out.x[j] = (in_ca * bd[j] + in_cb * da[j] + in_cd * ab[j]) * inv;
    const double ax = std::abs(out.x[j]);
    // An underflowed term of p_n (below 2^-900) errs by far less than u 2^-900.
    out.error[j] = 1.01 * (13 * u * std::max(p_n, 0x1p-900) + ax * out.det_error) * inv_abs + 2.02 * u * ax;
    ok &= std::abs(out.error[j]) <= DBL_MAX;  // finite
  }
  return ok;
}

// vertex_distance_bound's last steps for one lane (t = p - site: fields 13-15); -1 when
// not certain.
[[gnu::always_inline]] inline double bound_lane(const BoundInputs& in) {
  constexpr double u = 0x1p-53;
  const double* t = in.f + 13;
  PlanesMeet m;
  bool ok = meet_lane(in, m) & (m.det - m.det_error > 2e-9 * m.norms);
  double dist = 0, bound = 0;
  for (int j = 0; j < 3; ++j) {
    const double ae = std::abs(t[j] - m.x[j]);
    const double bj = m.error[j] + 1.01 * u * (std::abs(t[j]) + ae);
    ok &= (ae <= DBL_MAX) & (std::abs(bj) <= DBL_MAX);
    dist = std::max(dist, ae);
    bound = std::max(bound, bj);
  }
  const double r = dist * (1 + 4 * u) + 1.01 * bound;
  return ok ? r : -1;
}

}  // namespace

bool planes_meet(const FilterPlane& a, const FilterPlane& b, const FilterPlane& d, PlanesMeet& out) {
  const Point3 none{0, 0, 0};  // fields 13-15, not read
  return a.ok && b.ok && d.ok && meet_lane(bound_inputs(none, none, a, b, d), out);
}

double vertex_distance_bound(const Point3& p, const Point3& site, const FilterPlane& a, const FilterPlane& b,
                             const FilterPlane& d) {
  if (!(a.ok && b.ok && d.ok)) return -1;
  return bound_lane(bound_inputs(p, site, a, b, d));
}

namespace {

// The loop over the lanes, compiled twice: for AVX2 (four lanes) and for the default
// SSE2 (two), chosen at run time (kernel/cpu_features.hpp). No FMA in either, so every
// lane rounds as vertex_distance_bound does.
[[gnu::always_inline]] inline void bounds_loop(const double* const* f, std::size_t n, double* __restrict out) {
  for (std::size_t k = 0; k < n; ++k) {
    BoundInputs in;
    for (int j = 0; j < BoundInputs::kFields; ++j) in.f[j] = f[j][k];
    out[k] = bound_lane(in);
  }
}
[[gnu::target("avx2")]] void bounds_avx2(const double* const* f, std::size_t n, double* __restrict out) {
  bounds_loop(f, n, out);
}
void bounds_default(const double* const* f, std::size_t n, double* __restrict out) { bounds_loop(f, n, out); }

// The same for planes_meet (the planes' fields 0-12 only).
[[gnu::always_inline]] inline void meets_loop(const double* const* f, std::size_t n, PlanesMeet* __restrict out,
                                              char* __restrict found) {
  for (std::size_t k = 0; k < n; ++k) {
    BoundInputs in;
    for (int j = 0; j < BoundInputs::kPlaneFields; ++j) in.f[j] = f[j][k];
    found[k] = meet_lane(in, out[k]);
  }
}
[[gnu::target("avx2")]] void meets_avx2(const double* const* f, std::size_t n, PlanesMeet* __restrict out,
                                        char* __restrict found) {
  meets_loop(f, n, out, found);
}
void meets_default(const double* const* f, std::size_t n, PlanesMeet* __restrict out, char* __restrict found) {
  meets_loop(f, n, out, found);
}

}  // namespace

void BoundBatch::fields(const double* (&f)[BoundInputs::kFields]) const {
  for (int j = 0; j < BoundInputs::kFields; ++j) f[j] = data_.data() + j * kLanes;
}

void BoundBatch::bounds(std::span<double> out) const {
  const double* f[BoundInputs::kFields];
  fields(f);
  (cpu_has_avx2() ? bounds_avx2 : bounds_default)(f, std::min(size_, out.size()), out.data());
}

void BoundBatch::meets(std::span<PlanesMeet> out, std::span<char> found) const {
  const double* f[BoundInputs::kFields];
  fields(f);
  (cpu_has_avx2() ? meets_avx2 : meets_default)(f, std::min({size_, out.size(), found.size()}), out.data(),
                                                found.data());
}

}  // namespace dtlab
