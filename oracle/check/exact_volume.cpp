#include "oracle/check/exact_volume.hpp"

#include <gmp.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <vector>

namespace dtlab {
namespace {

struct Split {
  std::int64_t m;
  int k;
};

Split split(double x) {
  if (x == 0) return {0, INT_MAX};
  int e = 0;
  const double f = std::frexp(x, &e);
  return {static_cast<std::int64_t>(std::ldexp(f, 53)), e - 53};
}

class Scaled {
 public:
  explicit Scaled(std::span<const Point3> pts) : s_(3 * pts.size()) {
    for (std::size_t i = 0; i < pts.size(); ++i) {
      s_[3 * i] = split(pts[i].x);
      s_[3 * i + 1] = split(pts[i].y);
      s_[3 * i + 2] = split(pts[i].z);
    }
    for (const Split& s : s_)
      if (s.m != 0 && s.k < kmin_) kmin_ = s.k;
  }
  void load(mpz_t out, std::uint32_t point, int axis) const {
    const Split& s = s_[3 * point + axis];
    mpz_set_si(out, static_cast<long>(s.m));
    if (s.m != 0) mpz_mul_2exp(out, out, static_cast<mp_bitcnt_t>(s.k - kmin_));
  }
  int kmin() const { return kmin_ == INT_MAX ? 0 : kmin_; }

 private:
  std::vector<Split> s_;
  int kmin_ = INT_MAX;
};

struct Mpz {
  mpz_t v;
  Mpz() { mpz_init2(v, 512); }
  ~Mpz() { mpz_clear(v); }
  Mpz(const Mpz&) = delete;
  Mpz& operator=(const Mpz&) = delete;
};

// acc += det [p0; p1; p2] of the (already translated) rows r[0..8].
void add_det3(mpz_t acc, const Mpz* m, mpz_t t0, mpz_t t1) {
  auto r = [m](int i) { return m[i].v; };
  mpz_mul(t0, r(4), r(8));
  mpz_submul(t0, r(5), r(7));
  mpz_mul(t1, r(0), t0);
  mpz_add(acc, acc, t1);
  mpz_mul(t0, r(5), r(6));
  mpz_submul(t0, r(3), r(8));
  mpz_mul(t1, r(1), t0);
  mpz_add(acc, acc, t1);
  mpz_mul(t0, r(3), r(7));
  mpz_submul(t0, r(4), r(6));
  mpz_mul(t1, r(2), t0);
  mpz_add(acc, acc, t1);
}

double to_volume(const mpz_t v, int kmin) {
  long e = 0;
  const double d = mpz_get_d_2exp(&e, v);
  return std::ldexp(d, static_cast<int>(e + 3L * kmin)) / 6.0;
}

}  // namespace

VolumeSums exact_volume_sums(std::span<const Point3> points, std::span<const Tet> tets,
                             std::span<const std::array<std::uint32_t, 3>> boundary) {
  const Scaled sc(points);
  Mpz sum_t, sum_h, t0, t1, d[3];
  Mpz r[9];
  for (const Tet& k : tets) {
    for (int j = 0; j < 3; ++j) sc.load(d[j].v, k[3], j);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        sc.load(r[3 * i + j].v, k[i], j);
        mpz_sub(r[3 * i + j].v, r[3 * i + j].v, d[j].v);
      }
    add_det3(sum_t.v, r, t0.v, t1.v);
  }
  for (const auto& f : boundary) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) sc.load(r[3 * i + j].v, f[i], j);
    add_det3(sum_h.v, r, t0.v, t1.v);
  }
  VolumeSums out;
  out.equal = !tets.empty() && mpz_cmp(sum_t.v, sum_h.v) == 0;
  out.tets = to_volume(sum_t.v, sc.kmin());
  out.hull = to_volume(sum_h.v, sc.kmin());
  return out;
}

}  // namespace dtlab
