#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "families.hpp"
#include "predicates/adaptive.hpp"
#include "predicates/exact.hpp"

using namespace dtlab;
using namespace dtlab::test;

namespace {

void check_random(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const AdaptivePredicates ad;
  const ExactPredicates ex;
  int bad_o = 0, bad_i = 0;
  for (int i = 0; i < n; ++i) {
    const Point3 a = random_point(rng), b = random_point(rng), c = random_point(rng),
                 d = random_point(rng), e = random_point(rng);
    bad_o += ad.orient3d(a, b, c, d) != ex.orient3d(a, b, c, d);
    bad_i += ad.insphere(a, b, c, d, e) != ex.insphere(a, b, c, d, e);
  }
  CHECK(bad_o == 0);
  CHECK(bad_i == 0);
}

}  // namespace

TEST_CASE("adaptive matches exact on random input", "[adaptive]") { check_random(100000, 1); }

TEST_CASE("adaptive matches exact on 10^6 random inputs", "[adaptive][slow]") {
  check_random(1000000, 2);
}

TEST_CASE("adaptive matches exact on every hard family", "[adaptive]") {
  const AdaptivePredicates ad;
  const ExactPredicates ex;
  int bad = 0, zeros = 0;
  for (const Quad& q : hard_orient_inputs(3, 3000)) {
    const int s = ex.orient3d(q[0], q[1], q[2], q[3]);
    zeros += s == 0;
    bad += ad.orient3d(q[0], q[1], q[2], q[3]) != s;
  }
  CHECK(bad == 0);
  CHECK(zeros > 0);  // the families do contain exact degeneracies
  bad = zeros = 0;
  for (const Quint& q : hard_insphere_inputs(4, 3000)) {
    const int s = ex.insphere(q[0], q[1], q[2], q[3], q[4]);
    zeros += s == 0;
    bad += ad.insphere(q[0], q[1], q[2], q[3], q[4]) != s;
  }
  CHECK(bad == 0);
  CHECK(zeros > 0);
}

TEST_CASE("adaptive reaches every stage on the hard families", "[adaptive]") {
  AdaptiveStats st;
  const AdaptivePredicates ad{&st};
  for (const Quad& q : hard_orient_inputs(5, 1000)) ad.orient3d(q[0], q[1], q[2], q[3]);
  for (const Quint& q : hard_insphere_inputs(6, 1000)) ad.insphere(q[0], q[1], q[2], q[3], q[4]);
  for (int s = 0; s < static_cast<int>(AdaptiveStage::kCount); ++s) {
    INFO("stage " << kAdaptiveStageNames[s] << ": orient3d " << st.orient3d[s] << ", insphere "
                  << st.insphere[s]);
    CHECK(st.orient3d[s] + st.insphere[s] > 0);
  }
}

TEST_CASE("adaptive: extreme magnitudes and subnormals", "[adaptive]") {
  const AdaptivePredicates ad;
  const ExactPredicates ex;
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double big = std::numeric_limits<double>::max() / 4;
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> expo(-1074, 1020);
  int bad = 0;
  for (int i = 0; i < 20000; ++i) {
    // Coordinates with wildly mixed exponents, including subnormals and +-big/4.
    auto coord = [&]() {
      const int k = expo(rng);
      const double m = std::uniform_real_distribution<double>(-1, 1)(rng);
      const int pick = static_cast<int>(rng() % 16);
      return pick == 0 ? 0.0 : pick == 1 ? tiny : pick == 2 ? -big : std::ldexp(m, k);
    };
    auto pt = [&]() { return Point3{coord(), coord(), coord()}; };
    const Point3 a = pt(), b = pt(), c = pt(), d = pt(), e = pt();
    bad += ad.orient3d(a, b, c, d) != ex.orient3d(a, b, c, d);
    bad += ad.insphere(a, b, c, d, e) != ex.insphere(a, b, c, d, e);
  }
  CHECK(bad == 0);
}

TEST_CASE("adaptive: permutation identities", "[adaptive]") {
  const AdaptivePredicates ad;
  std::mt19937_64 rng(8);
  const auto quads = hard_orient_inputs(9, 300);
  int bad = 0;
  for (const Quad& q0 : quads) {
    std::array<int, 4> idx = {0, 1, 2, 3};
    const int s0 = ad.orient3d(q0[0], q0[1], q0[2], q0[3]);
    while (std::next_permutation(idx.begin(), idx.end())) {
      int inv = 0;  // parity by inversion count
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) inv += idx[i] > idx[j];
      const int s = ad.orient3d(q0[idx[0]], q0[idx[1]], q0[idx[2]], q0[idx[3]]);
      bad += s != (inv % 2 ? -s0 : s0);
    }
  }
  CHECK(bad == 0);
  // insphere is the sign of an alternating 5x5 determinant: any permutation of all
  // five points multiplies it by the permutation's sign.
  const auto quints = hard_insphere_inputs(10, 150);
  for (const Quint& q0 : quints) {
    std::array<int, 5> idx = {0, 1, 2, 3, 4};
    const int s0 = ad.insphere(q0[0], q0[1], q0[2], q0[3], q0[4]);
    for (int t = 0; t < 12; ++t) {
      std::shuffle(idx.begin(), idx.end(), rng);
      int inv = 0;
      for (int i = 0; i < 5; ++i)
        for (int j = i + 1; j < 5; ++j) inv += idx[i] > idx[j];
      const int s = ad.insphere(q0[idx[0]], q0[idx[1]], q0[idx[2]], q0[idx[3]], q0[idx[4]]);
      bad += s != (inv % 2 ? -s0 : s0);
    }
  }
  CHECK(bad == 0);
}

// (adaptive's exact-zero shortcut, a column of zero differences, still answers 0 first;
// build_delaunay, check and the Voronoi cells refuse non-finite input before any predicate.)
TEST_CASE("adaptive and exact: non-finite input reaching the exact stage is refused, not a silent 0", "[adaptive]") {
  const Point3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, n{std::numeric_limits<double>::quiet_NaN(), 0, 1},
      inf{0, 0, std::numeric_limits<double>::infinity()};
  CHECK_THROWS_AS(AdaptivePredicates{}.orient3d(o, x, y, n), std::domain_error);
  CHECK_THROWS_AS(ExactPredicates{}.orient3d(o, x, y, inf), std::domain_error);
  CHECK_THROWS_AS(AdaptivePredicates{}.insphere(o, x, y, inf, n), std::domain_error);
}

TEST_CASE("fused insphere-and-sides filter: every sign it decides is exact", "[adaptive]") {
  const ExactPredicates ex;
  const auto check = [&](const Quint& q, int& decided_sides, int& bad) {
    const InsphereSides r = adaptive_insphere_sides(q[0], q[1], q[2], q[3], q[4], nullptr);
    if (decided(r.insphere)) bad += to_int(to_sign(r.insphere)) != ex.insphere(q[0], q[1], q[2], q[3], q[4]);
    for (int k = 0; k < 4; ++k) {
      if (!decided(r.side[k])) continue;
      ++decided_sides;
      Quad o = {q[0], q[1], q[2], q[3]};
      o[k] = q[4];
      bad += to_int(to_sign(r.side[k])) != ex.orient3d(o[0], o[1], o[2], o[3]);
    }
  };
  int decided = 0, bad = 0;
  std::mt19937_64 rng(11);
  for (int i = 0; i < 20000; ++i) {
    Quint q;
    for (auto& p : q) p = random_point(rng);
    check(q, decided, bad);
  }
  CHECK(bad == 0);
  CHECK(decided > 4 * 20000 * 9 / 10);  // random input: the filter decides nearly all
  for (const Quint& q : hard_insphere_inputs(5, 3000)) check(q, decided, bad);
  for (const Quad& o : hard_orient_inputs(6, 3000)) {
    // Near-coplanar quads: each becomes an insphere input whose side 3 is orient3d(o).
    const Point3 far{o[0].x + 1, o[0].y - 2, o[0].z + 3};
    check({o[0], o[1], o[2], far, o[3]}, decided, bad);
  }
  CHECK(bad == 0);
}

namespace {

// Integer points on the sphere x^2 + y^2 + z^2 = r^2, moved by `offset` (an integer).
std::vector<Point3> integer_sphere(int r, double offset) {
  std::vector<Point3> out;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      for (int z = -r; z <= r; ++z)
        if (x * x + y * y + z * z == r * r) out.push_back({offset + x, offset + y, offset + z});
  return out;
}

struct StageRun {
  int wrong = 0;
  std::uint64_t integer = 0, later = 0;  // decided by the integer stage / by B..exact
};

// Random quints (and the quads of their first four points) drawn from `pts`, against
// the exact predicates; counts which stage decided the calls that stage A left open.
StageRun run_on(const std::vector<Point3>& pts, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  AdaptiveStats st;
  const AdaptivePredicates ad{&st};
  const ExactPredicates ex;
  StageRun r;
  for (int i = 0; i < 4000; ++i) {
    Point3 q[5];
    for (auto& p : q) p = pts[rng() % pts.size()];
    r.wrong += ad.insphere(q[0], q[1], q[2], q[3], q[4]) != ex.insphere(q[0], q[1], q[2], q[3], q[4]);
    r.wrong += ad.orient3d(q[0], q[1], q[2], q[3]) != ex.orient3d(q[0], q[1], q[2], q[3]);
  }
  const auto k = [](AdaptiveStage s) { return static_cast<int>(s); };
  r.integer = st.insphere[k(AdaptiveStage::kInteger)] + st.orient3d[k(AdaptiveStage::kInteger)];
  for (int s = k(AdaptiveStage::kB); s <= k(AdaptiveStage::kExact); ++s) r.later += st.insphere[s] + st.orient3d[s];
  return r;
}

}  // namespace

TEST_CASE("adaptive: the integer stage is exact where it applies and steps aside elsewhere", "[adaptive]") {
  // Cospherical integer points (insphere exactly 0 on every quint of distinct points),
  // near the origin and near the end of the integer range (offset 2^50 - 2^10).
  for (const double offset : {0.0, -12345.0, 0x1p50 - 0x1p10}) {
    const StageRun r = run_on(integer_sphere(25, offset), 1);
    INFO("offset " << offset);
    CHECK(r.wrong == 0);
    CHECK(r.integer > 0);
  }
  // Differences up to 600 > 2^9: insphere ties go on to stage B (orient3d may still
  // use the integer stage, whose bound is 2^16), and every answer stays exact.
  {
    const std::vector<Point3> wide = integer_sphere(300, 7);
    std::vector<Point3> some;
    for (std::size_t i = 0; i < wide.size(); i += 7) some.push_back(wide[i]);
    const StageRun r = run_on(some, 2);
    CHECK(r.wrong == 0);
    CHECK(r.later > 0);
  }
  // Half-integers and coordinates at 2^51 and beyond are not taken.
  for (const double offset : {0.5, 0x1p51}) {
    const StageRun r = run_on(integer_sphere(5, offset), 3);
    INFO("offset " << offset);
    CHECK(r.wrong == 0);
    CHECK(r.integer == 0);
    CHECK(r.later > 0);
  }
}
