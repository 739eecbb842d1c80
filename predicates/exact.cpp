#include "predicates/exact.hpp"

#include <gmp.h>

#include <climits>
#include <cmath>
#include <stdexcept>
#include <cstdint>

namespace dtlab {
namespace {

// GMP integers that live as long as the thread, so a call allocates nothing once warm.
struct MpzPool {
  static constexpr int kSize = 48;
  mpz_t v[kSize];
  MpzPool() {
    for (auto& x : v) mpz_init2(x, 256);
  }
  ~MpzPool() {
    for (auto& x : v) mpz_clear(x);
  }
  MpzPool(const MpzPool&) = delete;
  MpzPool& operator=(const MpzPool&) = delete;
};

MpzPool& pool() {
  thread_local MpzPool p;
  return p;
}

// x = m * 2^k with m an integer, |m| < 2^53 (k is meaningless for x == 0).
struct Split {
  std::int64_t m;
  int k;
};

Split split_double(double x) {
  if (x == 0) return {0, INT_MAX};
  int e = 0;
  const double f = std::frexp(x, &e);  // x = f * 2^e, 0.5 <= |f| < 1
  return {static_cast<std::int64_t>(std::ldexp(f, 53)), e - 53};
}

// Loads n doubles as integers scaled by one common power of two. A NaN or an infinity
// has no sign to give: std::domain_error (never a silent 0).
bool load_scaled(const double* xs, int n, mpz_t* out) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(xs[i])) throw std::domain_error("exact predicate: non-finite coordinate");
  Split s[15];
  int kmin = INT_MAX;
  for (int i = 0; i < n; ++i) {
    s[i] = split_double(xs[i]);
    if (s[i].m != 0 && s[i].k < kmin) kmin = s[i].k;
  }
  for (int i = 0; i < n; ++i) {
    mpz_set_si(out[i], static_cast<long>(s[i].m));
    if (s[i].m != 0) mpz_mul_2exp(out[i], out[i], static_cast<mp_bitcnt_t>(s[i].k - kmin));
  }
  return true;
}

// r = p*q - s*t
void det2(mpz_t r, const mpz_t p, const mpz_t q, const mpz_t s, const mpz_t t, mpz_t tmp) {
  mpz_mul(r, p, q);
  mpz_mul(tmp, s, t);
  mpz_sub(r, r, tmp);
}

}  // namespace

int exact_orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const double xs[12] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  MpzPool& P = pool();
  mpz_t* v = P.v;  // v[0..11] coordinates, v[12..20] differences to d
  if (!load_scaled(xs, 12, v)) return 0;
  mpz_t* df = v + 12;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) mpz_sub(df[3 * i + j], v[3 * i + j], v[9 + j]);
  // det [a-d; b-d; c-d] by the first row.
  mpz_t *m = v + 21, *tmp = v + 24, *acc = v + 25;
  det2(m[0], df[4], df[8], df[5], df[7], *tmp);  // bdy*cdz - bdz*cdy
  det2(m[1], df[5], df[6], df[3], df[8], *tmp);  // bdz*cdx - bdx*cdz
  det2(m[2], df[3], df[7], df[4], df[6], *tmp);  // bdx*cdy - bdy*cdx
  mpz_mul(*acc, df[0], m[0]);
  mpz_addmul(*acc, df[1], m[1]);
  mpz_addmul(*acc, df[2], m[2]);
  return mpz_sgn(*acc);
}

int exact_insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                   const Point3& e) {
  const double xs[15] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z,
                         d.x, d.y, d.z, e.x, e.y, e.z};
  MpzPool& P = pool();
  mpz_t* v = P.v;
  if (!load_scaled(xs, 15, v)) return 0;
  // r[i][j]: coordinate j of point i minus e (i = a,b,c,d).
  mpz_t* r = v + 15;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) mpz_sub(r[3 * i + j], v[3 * i + j], v[12 + j]);
  auto X = [&](int i) { return r[3 * i]; };
  auto Y = [&](int i) { return r[3 * i + 1]; };
  auto Z = [&](int i) { return r[3 * i + 2]; };
  mpz_t* t = v + 27;  // scratch
  mpz_t *ab = t, *bc = t + 1, *cd = t + 2, *da = t + 3, *ac = t + 4, *bd = t + 5;
  mpz_t* tmp = t + 6;
  det2(*ab, X(0), Y(1), X(1), Y(0), *tmp);
  det2(*bc, X(1), Y(2), X(2), Y(1), *tmp);
  det2(*cd, X(2), Y(3), X(3), Y(2), *tmp);
  det2(*da, X(3), Y(0), X(0), Y(3), *tmp);
  det2(*ac, X(0), Y(2), X(2), Y(0), *tmp);
  det2(*bd, X(1), Y(3), X(3), Y(1), *tmp);
  mpz_t *abc = t + 7, *bcd = t + 8, *cda = t + 9, *dab = t + 10;
  // abc = az*bc - bz*ac + cz*ab, and cyclically (same formulas as naive.hpp).
  mpz_mul(*abc, Z(0), *bc);
  mpz_submul(*abc, Z(1), *ac);
  mpz_addmul(*abc, Z(2), *ab);
  mpz_mul(*bcd, Z(1), *cd);
  mpz_submul(*bcd, Z(2), *bd);
  mpz_addmul(*bcd, Z(3), *bc);
  mpz_mul(*cda, Z(2), *da);
  mpz_addmul(*cda, Z(3), *ac);
  mpz_addmul(*cda, Z(0), *cd);
  mpz_mul(*dab, Z(3), *ab);
  mpz_addmul(*dab, Z(0), *bd);
  mpz_addmul(*dab, Z(1), *da);
  mpz_t* lift = t + 11;  // 4 entries
  for (int i = 0; i < 4; ++i) {
    mpz_mul(lift[i], X(i), X(i));
    mpz_addmul(lift[i], Y(i), Y(i));
    mpz_addmul(lift[i], Z(i), Z(i));
  }
  mpz_t* acc = t + 15;
  mpz_mul(*acc, lift[3], *abc);
  mpz_submul(*acc, lift[2], *dab);
  mpz_addmul(*acc, lift[1], *cda);
  mpz_submul(*acc, lift[0], *bcd);
  return mpz_sgn(*acc);
}

}  // namespace dtlab
