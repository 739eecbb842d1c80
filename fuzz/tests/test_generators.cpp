#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include "fuzz/families.hpp"
#include "fuzz/generators.hpp"
#include "fuzz/lattice_solutions.hpp"
#include "fuzz/rounded_transform.hpp"
#include "fuzz/tests/exact_int.hpp"

using namespace dtlab;
using namespace dtlab::fuzz;
namespace t = dtlab::fuzz::test;

namespace {

bool same_bits(const std::vector<Point3>& a, const std::vector<Point3>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Point3)) == 0);
}

std::vector<Point3> gen(const std::string& name, std::size_t n, std::uint64_t seed) {
  const Family* f = find_family(name);
  REQUIRE(f != nullptr);
  return f->generate(n, seed);
}

bool all_distinct(const std::vector<Point3>& pts) {
  std::set<Point3, decltype(&lex_less)> s(&lex_less);
  for (const auto& p : pts)
    if (!s.insert(p).second) return false;
  return true;
}

bool all_small_ints(const std::vector<Point3>& pts) {
  for (const auto& p : pts)
    if (!t::is_small_int(p)) return false;
  return true;
}

// Indices of three non-collinear points, or false.
bool find_triangle(const std::vector<Point3>& pts, std::size_t& i, std::size_t& j, std::size_t& k) {
  for (i = 0; i < pts.size(); ++i)
    for (j = i + 1; j < pts.size(); ++j)
      for (k = j + 1; k < pts.size(); ++k)
        if (!t::collinear(pts[i], pts[j], pts[k])) return true;
  return false;
}

}  // namespace

TEST_CASE("every family returns exactly n points, reproducibly", "[fuzz][generators]") {
  REQUIRE(families().size() >= 18);
  for (const auto& f : families()) {
    INFO(f.name);
    CHECK_FALSE(f.description.empty());
    for (std::size_t n : {0, 1, 2, 5, 64, 300}) {
      const auto a = f.generate(n, 12345);
      CHECK(a.size() == n);
      CHECK(same_bits(a, f.generate(n, 12345)));
      for (const auto& p : a) CHECK((std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)));
    }
    CHECK_FALSE(same_bits(f.generate(64, 1), f.generate(64, 2)));
  }
}

TEST_CASE("family names are unique and findable", "[fuzz][generators]") {
  std::set<std::string> names;
  for (const auto& f : families()) {
    CHECK(names.insert(f.name).second);
    CHECK(find_family(f.name) == &f);
  }
  CHECK(find_family("no_such_family") == nullptr);
}

TEST_CASE("the int128 predicates of the tests get known signs right", "[fuzz][generators]") {
  const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
  // Shewchuk: orient3d(a,b,c,d) > 0 iff d is below the plane of a, b, c (ccw from above).
  CHECK(t::orient3d(a, b, c, Point3{0, 0, -1}) > 0);
  const Point3 down{0, 0, -1};
  CHECK(t::insphere(a, b, c, down, Point3{0.0, 0.0, 0.0}) == 0);  // a vertex: on the sphere
  CHECK(t::insphere(a, c, b, d, Point3{1, 1, 1}) == 0);            // cube corner: cospherical
  CHECK(t::orient3d(a, c, b, d) > 0);
  CHECK(t::insphere(a, c, b, d, Point3{2, 2, 2}) < 0);  // outside
}

TEST_CASE("lattice solutions lie on their sphere and circle", "[fuzz][generators]") {
  for (std::int64_t r : {1, 5, 25, 50}) {
    const auto pts = sphere_lattice_points(r);
    CHECK(pts.size() >= 6);
    for (const auto& p : pts) CHECK(p.x * p.x + p.y * p.y + p.z * p.z == double(r * r));
  }
  CHECK(sphere_lattice_points(3).size() == 30);  // r3(9) = 30
  std::size_t expected = 8;
  for (std::int64_t m : rich_circle_radii2()) {
    const auto pts = circle_lattice_points(m);
    CHECK(pts.size() == expected);  // 4 * 2^k for k primes = 1 mod 4
    expected *= 2;
    for (const auto& p : pts) CHECK(static_cast<std::int64_t>(p.x * p.x) + static_cast<std::int64_t>(p.y * p.y) == m);
  }
  CHECK(sphere_lattice_points(sphere_radius_with(500)).size() >= 500);
}

TEST_CASE("uniform and clustered stay in their boxes", "[fuzz][generators]") {
  for (const auto& p : gen("uniform", 500, 3)) {
    CHECK((p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1 && p.z >= 0 && p.z < 1));
  }
  for (const auto& p : gen("clustered", 500, 3)) CHECK((std::abs(p.x) < 3 && std::abs(p.y) < 3));
}

TEST_CASE("lattice families are distinct integer grid points", "[fuzz][generators]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    const auto full = gen("lattice", 125, seed);
    CHECK(all_small_ints(full));
    CHECK(all_distinct(full));
    double lo = full[0].x, hi = full[0].x;
    for (const auto& p : full) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    CHECK(hi - lo == 4);  // 125 = 5^3: a full 5x5x5 block
    const auto sub = gen("lattice_subset", 200, seed);
    CHECK(all_small_ints(sub));
    CHECK(all_distinct(sub));
  }
}

TEST_CASE("cospherical points are exactly on one sphere", "[fuzz][generators]") {
  for (std::uint64_t seed : {1, 2, 3, 4}) {
    const auto pts = gen("cospherical", 120, seed);
    REQUIRE(all_small_ints(pts));
    CHECK(all_distinct(pts));
    // Four affinely independent points fix the sphere; every other is on it.
    std::size_t i, j, k;
    REQUIRE(find_triangle(pts, i, j, k));
    std::size_t l = 0;
    while (l < pts.size() && t::orient3d(pts[i], pts[j], pts[k], pts[l]) == 0) ++l;
    REQUIRE(l < pts.size());
    for (const auto& e : pts) CHECK(t::insphere(pts[i], pts[j], pts[k], pts[l], e) == 0);
  }
  // Past 1024 points, concentric shells: all still integer and distinct.
  const auto many = gen("cospherical", 1500, 9);
  CHECK(all_small_ints(many));
  CHECK(all_distinct(many));
}

TEST_CASE("rings: every point is on an exact axis-aligned circle of input points",
          "[fuzz][generators]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    const auto pts = gen("rings", 40, seed);
    REQUIRE(all_small_ints(pts));
    CHECK(all_distinct(pts));
    for (const auto& p : pts) {
      bool on_ring = false;
      for (int axis = 0; axis < 3 && !on_ring; ++axis) {
        std::vector<Point3> plane;
        for (const auto& q : pts) {
          const double pc = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
          const double qc = axis == 0 ? q.x : axis == 1 ? q.y : q.z;
          if (qc == pc && !(q == p)) plane.push_back(q);
        }
        for (std::size_t a = 0; a < plane.size() && !on_ring; ++a)
          for (std::size_t b = a + 1; b < plane.size() && !on_ring; ++b) {
            if (t::collinear2d(p, plane[a], plane[b], axis)) continue;
            for (std::size_t c = b + 1; c < plane.size() && !on_ring; ++c)
              on_ring = t::incircle2d(p, plane[a], plane[b], plane[c], axis) == 0;
          }
      }
      CHECK(on_ring);
    }
  }
}

TEST_CASE("cylinder: coaxial rings of one radius", "[fuzz][generators]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    const auto pts = gen("cylinder", 60, seed);
    REQUIRE(all_small_ints(pts));
    CHECK(all_distinct(pts));
    std::set<double> heights;
    for (const auto& p : pts) heights.insert(p.z);
    CHECK(heights.size() >= 2);
    // Seen from the axis (dropping z) every point is on one circle.
    std::size_t a = 0, b = 1, c = 2;
    bool found = false;
    for (a = 0; a < pts.size() && !found; ++a)
      for (b = a + 1; b < pts.size() && !found; ++b)
        for (c = b + 1; c < pts.size() && !found; ++c)
          found = !t::collinear2d(pts[a], pts[b], pts[c], 2);
    REQUIRE(found);
    --a, --b, --c;
    for (const auto& p : pts) CHECK(t::incircle2d(pts[a], pts[b], pts[c], p, 2) == 0);
    // Two rings at different heights are cospherical.
    std::vector<Point3> two;
    for (const auto& p : pts)
      if (p.z == *heights.begin() || p.z == *std::next(heights.begin())) two.push_back(p);
    std::size_t i, j, k;
    REQUIRE(find_triangle(two, i, j, k));
    std::size_t l = 0;
    while (t::orient3d(two[i], two[j], two[k], two[l]) == 0) ++l;
    for (const auto& e : two) CHECK(t::insphere(two[i], two[j], two[k], two[l], e) == 0);
  }
}

TEST_CASE("coplanar families lie on few exact parallel planes", "[fuzz][generators]") {
  const auto count_planes = [](const std::vector<Point3>& pts) {
    // The normal of some triangle among the first 16 points that puts every
    // point on the fewest parallel planes.
    std::size_t best = pts.size();
    const std::size_t m = std::min<std::size_t>(16, pts.size());
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = i + 1; j < m; ++j)
        for (std::size_t k = j + 1; k < m; ++k) {
          if (t::collinear(pts[i], pts[j], pts[k])) continue;
          const auto a = t::to_i3(pts[i]);
          const auto nrm = t::cross(t::sub(t::to_i3(pts[j]), a), t::sub(t::to_i3(pts[k]), a));
          std::set<t::i128> offsets;
          for (const auto& p : pts) offsets.insert(t::dot(nrm, t::to_i3(p)));
          best = std::min(best, offsets.size());
        }
    return best;
  };
  for (std::uint64_t seed : {1, 2, 3, 4}) {
    const auto slabs = gen("coplanar_slabs", 100, seed);
    REQUIRE(all_small_ints(slabs));
    CHECK(all_distinct(slabs));
    const std::size_t planes = count_planes(slabs);
    CHECK(planes >= 2);
    CHECK(planes <= 5);
    const auto flat = gen("coplanar_all", 100, seed);
    REQUIRE(all_small_ints(flat));
    CHECK(all_distinct(flat));
    CHECK(count_planes(flat) == 1);
  }
}

TEST_CASE("collinear: most points share a line with two others", "[fuzz][generators]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    const auto pts = gen("collinear", 60, seed);
    REQUIRE(all_small_ints(pts));
    CHECK(all_distinct(pts));
    std::size_t on_line = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      bool found = false;
      for (std::size_t j = 0; j < pts.size() && !found; ++j)
        for (std::size_t k = j + 1; k < pts.size() && !found; ++k)
          found = j != i && k != i && t::collinear(pts[i], pts[j], pts[k]);
      on_line += found;
    }
    CHECK(on_line * 2 >= pts.size());
  }
}

TEST_CASE("duplicates: exact repeats, some differing only in the sign of zero",
          "[fuzz][generators]") {
  std::size_t repeats = 0, signed_zero_repeats = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto pts = gen("duplicates", 100, seed);
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (pts[i] == pts[j]) {
          ++repeats;
          if (std::memcmp(&pts[i], &pts[j], sizeof(Point3)) != 0) ++signed_zero_repeats;
          break;
        }
  }
  CHECK(repeats >= 5 * 15);
  CHECK(signed_zero_repeats > 0);
}

TEST_CASE("near-degenerate families are rounded images of exact configurations",
          "[fuzz][generators]") {
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (std::uint64_t seed : {1, 2, 3, 4, 5}) {
    Rng replay(seed);
    const auto base = exact_configuration(80, replay);
    REQUIRE(all_small_ints(base));

    const auto jitter = gen("ulp_jitter", 80, seed);
    std::size_t moved = 0;
    for (std::size_t i = 0; i < base.size(); ++i) {
      const double b[3] = {base[i].x, base[i].y, base[i].z};
      const double p[3] = {jitter[i].x, jitter[i].y, jitter[i].z};
      for (int c = 0; c < 3; ++c) {
        CHECK(p[c] >= std::nextafter(b[c], -inf));
        CHECK(p[c] <= std::nextafter(b[c], inf));
        moved += p[c] != b[c];
      }
    }
    CHECK(moved > 0);

    const auto scaled = gen("extreme_scale", 80, seed);
    int k = 0;  // recover the exponent from the first non-zero coordinate
    for (const auto& p : base)
      if (p.x != 0) {
        const auto i = &p - base.data();
        k = std::ilogb(scaled[i].x) - std::ilogb(p.x);
        break;
      }
    CHECK(k >= -500);
    CHECK(k <= 500);
    for (std::size_t i = 0; i < base.size(); ++i) {
      CHECK(std::ldexp(scaled[i].x, -k) == base[i].x);
      CHECK(std::ldexp(scaled[i].y, -k) == base[i].y);
      CHECK(std::ldexp(scaled[i].z, -k) == base[i].z);
    }

    const auto tiny = gen("subnormal", 80, seed);
    for (std::size_t i = 0; i < base.size(); ++i) {
      for (double v : {tiny[i].x, tiny[i].y, tiny[i].z})
        CHECK((v == 0 || std::fpclassify(v) == FP_SUBNORMAL));
      CHECK(std::ldexp(tiny[i].x, 1060) == base[i].x);
      CHECK(std::ldexp(tiny[i].z, 1060) == base[i].z);
    }
  }
}

TEST_CASE("rational rotations are exact rotations before rounding", "[fuzz][generators]") {
  // M = n R has integer entries with M M^T = n^2 I: check it in integers.
  Rng rng(17);
  for (int trial = 0; trial < 50; ++trial) {
    const std::int64_t a = rng.range(-20, 20), b = rng.range(-20, 20), c = rng.range(-20, 20),
                       d = rng.range(-20, 20);
    const std::int64_t n = a * a + b * b + c * c + d * d;
    if (n == 0) continue;
    const auto r = rational_rotation(a, b, c, d);
    std::int64_t m[9];
    for (int i = 0; i < 9; ++i) m[i] = std::llround(r[i] * static_cast<double>(n));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const std::int64_t s = m[3 * i] * m[3 * j] + m[3 * i + 1] * m[3 * j + 1] + m[3 * i + 2] * m[3 * j + 2];
        CHECK(s == (i == j ? n * n : 0));
      }
  }
}

TEST_CASE("near_degenerate moves an exact configuration off its degeneracy by rounding only",
          "[fuzz][generators]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    Rng replay(seed);
    const auto base = exact_configuration(50, replay);
    const RoundedTransform tr = random_transform(replay);
    const auto pts = gen("near_degenerate", 50, seed);
    for (std::size_t i = 0; i < pts.size(); ++i) CHECK(pts[i] == tr.apply(base[i]));
  }
}

TEST_CASE("far_translate snaps to a coarse grid far from the origin", "[fuzz][generators]") {
  for (std::uint64_t seed : {1, 2, 3}) {
    const auto pts = gen("far_translate", 400, seed);
    std::set<double> xs;
    for (const auto& p : pts) {
      CHECK(std::abs(p.x) >= 0x1p30);
      xs.insert(p.x);
    }
    CHECK(xs.size() <= 4097);
  }
}

TEST_CASE("kettner grid: anchors plus ulp steps from (0.5, 0.5, 0.5)", "[fuzz][generators]") {
  for (const auto& a : kKettnerAnchors) CHECK(a.x - 2 * a.y + a.z == 0);
  const auto pts = gen("kettner_grid", 300, 5);
  CHECK(all_distinct(pts));
  std::size_t anchors = 0;
  for (const auto& p : pts) {
    bool is_anchor = false;
    for (const auto& a : kKettnerAnchors) is_anchor |= p == a;
    if (is_anchor) {
      ++anchors;
      continue;
    }
    for (double v : {p.x, p.y, p.z}) {
      const double steps = (v - kKettnerBase) / kKettnerStep;  // exact: both powers of two
      CHECK(steps == std::floor(steps));
      CHECK(steps >= 0);
      CHECK(steps < kKettnerSide);
    }
  }
  CHECK(anchors == 4);
}

TEST_CASE("moment curve points are exact (t, t^2, t^3)", "[fuzz][generators]") {
  const auto pts = gen("moment_curve", 300, 8);
  CHECK(all_distinct(pts));
  for (const auto& p : pts) {
    const auto ti = static_cast<t::i128>(p.x);
    CHECK(static_cast<double>(ti) == p.x);
    CHECK(static_cast<t::i128>(p.y) == ti * ti);
    CHECK(static_cast<t::i128>(p.z) == ti * ti * ti);
  }
  // The largest parameter keeps t^3 below 2^53.
  const t::i128 big = 208063;
  CHECK(big * big * big < (t::i128{1} << 53));
}
