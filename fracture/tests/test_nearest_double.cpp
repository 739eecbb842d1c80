// Written coordinates are the exact values rounded to the nearest double: compared with
// MPFR's correctly rounded conversion, and independent of how far CGAL's lazy numbers
// were evaluated (the state that differed between -O1 and -O3 builds).
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include <mpfr.h>

#include "fracture/fracture.hpp"
#include "fracture/nearest_double.hpp"
#include "fracture/tests/meshes.hpp"

using namespace dtlab;
using FT = CGAL::Epeck::FT;
using ET = FT::ET;

namespace {

template <class Q>
const __mpq_struct* mpq_of(const Q& q) {
  if constexpr (std::is_same_v<Q, CGAL::Gmpq>)
    return q.mpq();
  else
    return q.get_mpq_t();
}

// MPFR's round to nearest, ties to even, with IEEE subnormals.
double mpfr_nearest(const ET& x) {
  const mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
  mpfr_set_emin(-1073);
  mpfr_set_emax(1024);
  mpfr_t y;
  mpfr_init2(y, 53);
  const int r = mpfr_set_q(y, mpq_of(x), MPFR_RNDN);
  mpfr_subnormalize(y, r, MPFR_RNDN);
  const double d = mpfr_get_d(y, MPFR_RNDN);
  mpfr_clear(y);
  mpfr_set_emin(emin);
  mpfr_set_emax(emax);
  return d;
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

}  // namespace

TEST_CASE("nearest_double rounds exact rationals as MPFR does", "[fracture][rounding]") {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int64_t> num(-(std::int64_t(1) << 62), std::int64_t(1) << 62);
  std::uniform_int_distribution<std::int64_t> den(1, std::int64_t(1) << 40);
  for (int k = 0; k < 20000; ++k) {
    const ET x = ET(ET(double(num(rng))) / ET(double(den(rng))) + ET(1) / ET(double(den(rng))));
    INFO("case " << k);
    CHECK(same_bits(nearest_double(x), mpfr_nearest(x)));
  }
  // Ties between adjacent doubles go to the even one; subnormals; a negative tie.
  const double d = 1.0 + std::ldexp(1.0, -52);  // odd last bit
  const ET tie_up((ET(d) + ET(std::nextafter(d, 2.0))) / 2);
  const ET tie_down((ET(d) + ET(std::nextafter(d, 0.0))) / 2);
  const ET minus_tie(-tie_up);
  CHECK(same_bits(nearest_double(tie_up), mpfr_nearest(tie_up)));
  CHECK(same_bits(nearest_double(tie_up), std::nextafter(d, 2.0)));  // the even neighbour
  CHECK(same_bits(nearest_double(tie_down), mpfr_nearest(tie_down)));
  CHECK(same_bits(nearest_double(minus_tie), mpfr_nearest(minus_tie)));
  const ET tiny(std::numeric_limits<double>::denorm_min());
  const std::vector<ET> small = {ET(tiny / 3), ET(tiny * 5 / 2), ET(tiny * 7 / 2), ET(-tiny / 2), ET(tiny / 2), ET(0)};
  for (const ET& x : small) CHECK(same_bits(nearest_double(x), mpfr_nearest(x)));
}

TEST_CASE("a lazy number rounds to the same double before and after its exact value is known", "[fracture][rounding]") {
  // Chains of operations whose intervals are several ulps wide: their midpoints are not
  // the nearest double of the value (the old rounding returned the midpoint).
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 2000; ++k) {
    FT v = u(rng);
    for (int j = 0; j < 12; ++j) v = v * FT(u(rng)) + FT(u(rng)) / FT(3 + j);
    const double before = nearest_double(v);  // from the interval or the exact value
    const ET& x = v.exact();                  // now the interval is the tight one of x
    INFO("case " << k);
    CHECK(same_bits(before, mpfr_nearest(x)));
    CHECK(same_bits(nearest_double(v), before));
  }
}

TEST_CASE("the written pieces do not depend on whether the exact tiling was proven", "[fracture][rounding]") {
  // --exact-tiling evaluates every piece's exact coordinates before they are written,
  // so the lazy numbers are in another state: the written doubles must be the same.
  FractureOptions o;
  o.pieces = 12;
  o.seed = 5;
  o.threads = 1;
  const FractureResult plain = fracture_mesh(test::small_torus(), o);
  o.exact_tiling = true;
  const FractureResult proven = fracture_mesh(test::small_torus(), o);
  REQUIRE(plain.pieces.size() == proven.pieces.size());
  std::size_t vertices = 0, differ = 0;
  for (std::size_t i = 0; i < plain.pieces.size(); ++i) {
    const auto& a = plain.pieces[i].geometry.mesh.vertices;
    const auto& b = proven.pieces[i].geometry.mesh.vertices;
    REQUIRE(a.size() == b.size());
    for (std::size_t k = 0; k < a.size(); ++k, ++vertices)
      differ += !(same_bits(a[k].x, b[k].x) && same_bits(a[k].y, b[k].y) && same_bits(a[k].z, b[k].z));
  }
  INFO(differ << " of " << vertices << " vertices differ");
  CHECK(vertices > 1000);
  CHECK(differ == 0);
}
