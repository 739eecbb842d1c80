#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <algorithm>

#include "families.hpp"
#include "predicates/adaptive.hpp"
#include "predicates/exact.hpp"
#include "predicates/perturbed.hpp"

using namespace dtlab;
using namespace dtlab::test;

namespace {

// Sign of the lifted determinant with explicit lift offsets: det of the rows
// (p - e, |p - e|^2 + off_p - off_e), p = a..d, where off = delta^r and r = 1 for the
// lexicographically largest of the five points, 2 for the next, ..., 5 for the
// smallest. delta = 2^-64 is far below any minor of these small integer inputs, so
// this is the sign for delta -> 0+. Everything is scaled by 2^(64*5) to stay integer.
int lifted_sign(const Quint& q) {
  std::array<int, 5> order = {0, 1, 2, 3, 4};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return lex_less(q[j], q[i]); });
  std::array<mpz_class, 5> off;  // off_i * 2^320
  for (int r = 0; r < 5; ++r) {
    mpz_class v = 1;
    mpz_mul_2exp(v.get_mpz_t(), v.get_mpz_t(), 64 * (5 - (r + 1)));
    off[order[r]] = v;
  }
  mpz_class scale = 1;
  mpz_mul_2exp(scale.get_mpz_t(), scale.get_mpz_t(), 320);
  mpz_class m[4][4];
  for (int i = 0; i < 4; ++i) {
    const mpz_class x = static_cast<long>(q[i].x - q[4].x), y = static_cast<long>(q[i].y - q[4].y),
                    z = static_cast<long>(q[i].z - q[4].z);
    m[i][0] = x;
    m[i][1] = y;
    m[i][2] = z;
    m[i][3] = (x * x + y * y + z * z) * scale + off[i] - off[4];
  }
  // 4x4 determinant by cofactors along the first row.
  auto det3 = [&](int c0, int c1, int c2, int r0, int r1, int r2) -> mpz_class {
    return m[r0][c0] * (m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]) -
           m[r0][c1] * (m[r1][c0] * m[r2][c2] - m[r1][c2] * m[r2][c0]) +
           m[r0][c2] * (m[r1][c0] * m[r2][c1] - m[r1][c1] * m[r2][c0]);
  };
  mpz_class det = 0;
  for (int c = 0; c < 4; ++c) {
    int cols[3], k = 0;
    for (int j = 0; j < 4; ++j)
      if (j != c) cols[k++] = j;
    mpz_class minor = m[0][c] * det3(cols[0], cols[1], cols[2], 1, 2, 3);
    if (c % 2) det -= minor; else det += minor;
  }
  return sgn(det);
}

bool distinct(const Quint& q) {
  for (int i = 0; i < 5; ++i)
    for (int j = i + 1; j < 5; ++j)
      if (q[i] == q[j]) return false;
  return true;
}

}  // namespace

TEST_CASE("perturbed exact never answers 0 on cospherical, non-coplanar input", "[perturbed]") {
  const Perturbed<ExactPredicates> pe{};
  const ExactPredicates ex;
  std::mt19937_64 rng(11);
  int cospherical = 0;
  for (int i = 0; i < 3000; ++i) {
    const Quint q = cospherical_int_quint(rng);
    if (ex.orient3d(q[0], q[1], q[2], q[3]) == 0) continue;
    REQUIRE(ex.insphere(q[0], q[1], q[2], q[3], q[4]) == 0);
    ++cospherical;
    const int s = pe.insphere(q[0], q[1], q[2], q[3], q[4]);
    CHECK(s != 0);
    CHECK(s == lifted_sign(q));
  }
  CHECK(cospherical > 1000);
}

TEST_CASE("perturbed exact equals the explicitly lifted determinant", "[perturbed]") {
  // Tiny integer grids: lots of coplanar and cospherical subsets.
  const Perturbed<ExactPredicates> pe{};
  const ExactPredicates ex;
  std::mt19937_64 rng(12);
  int checked = 0, ties = 0;
  for (int i = 0; i < 20000; ++i) {
    Quint q;
    for (Point3& p : q) p = small_int_point(rng, 2);
    if (!distinct(q) || ex.orient3d(q[0], q[1], q[2], q[3]) == 0) continue;
    ++checked;
    ties += ex.insphere(q[0], q[1], q[2], q[3], q[4]) == 0;
    const int s = pe.insphere(q[0], q[1], q[2], q[3], q[4]);
    REQUIRE(s != 0);
    REQUIRE(s == lifted_sign(q));
  }
  CHECK(ties > 100);
  CHECK(checked > 5000);
}

TEST_CASE("perturbed adaptive equals perturbed exact on the hard families", "[perturbed]") {
  const Perturbed<ExactPredicates> pe{};
  const Perturbed<AdaptivePredicates> pa{};
  int bad = 0;
  for (const Quint& q : hard_insphere_inputs(13, 500)) {
    if (!distinct(q)) continue;
    bad += pa.insphere(q[0], q[1], q[2], q[3], q[4]) != pe.insphere(q[0], q[1], q[2], q[3], q[4]);
  }
  CHECK(bad == 0);
}

TEST_CASE("perturbed insphere does not depend on the order of a,b,c,d", "[perturbed]") {
  // The perturbed 5x5 determinant stays alternating: permuting the five points
  // multiplies the perturbed sign by the permutation's sign.
  const Perturbed<ExactPredicates> pe{};
  const ExactPredicates ex;
  std::mt19937_64 rng(14);
  int bad = 0;
  for (int i = 0; i < 3000; ++i) {
    Quint q;
    for (Point3& p : q) p = small_int_point(rng, 2);
    if (!distinct(q)) continue;
    std::array<int, 5> idx = {0, 1, 2, 3, 4};
    std::shuffle(idx.begin(), idx.end(), rng);
    if (ex.orient3d(q[0], q[1], q[2], q[3]) == 0 ||
        ex.orient3d(q[idx[0]], q[idx[1]], q[idx[2]], q[idx[3]]) == 0)
      continue;
    int inv = 0;
    for (int a = 0; a < 5; ++a)
      for (int b = a + 1; b < 5; ++b) inv += idx[a] > idx[b];
    const int s0 = pe.insphere(q[0], q[1], q[2], q[3], q[4]);
    const int s = pe.insphere(q[idx[0]], q[idx[1]], q[idx[2]], q[idx[3]], q[idx[4]]);
    bad += s != (inv % 2 ? -s0 : s0);
  }
  CHECK(bad == 0);
}
