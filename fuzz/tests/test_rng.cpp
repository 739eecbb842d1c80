#include <algorithm>
#include <catch2/catch.hpp>
#include <numeric>

#include "fuzz/rng.hpp"

using dtlab::fuzz::Rng;

TEST_CASE("Rng follows the standard mt19937_64 sequence", "[fuzz][rng]") {
  // The standard fixes the 10000th output of a default-seeded mt19937_64.
  Rng rng(5489u);
  std::uint64_t v = 0;
  for (int i = 0; i < 10000; ++i) v = rng.next();
  CHECK(v == 9981545732273789042ULL);
}

TEST_CASE("Rng conversions are in range and reproducible", "[fuzz][rng]") {
  Rng a(7), b(7);
  for (int i = 0; i < 2000; ++i) {
    const double u = a.unit();
    CHECK(u >= 0.0);
    CHECK(u < 1.0);
    CHECK(u == b.unit());
    const std::int64_t r = a.range(-3, 5);
    CHECK(r >= -3);
    CHECK(r <= 5);
    CHECK(r == b.range(-3, 5));
  }
  CHECK(a.below(1) == 0);
}

TEST_CASE("Rng::below covers its range without bias we can see", "[fuzz][rng]") {
  Rng rng(11);
  int counts[6] = {};
  for (int i = 0; i < 60000; ++i) ++counts[rng.below(6)];
  for (int c : counts) CHECK(std::abs(c - 10000) < 500);
}

TEST_CASE("Rng::shuffle permutes deterministically", "[fuzz][rng]") {
  std::vector<int> v(100), w;
  std::iota(v.begin(), v.end(), 0);
  w = v;
  Rng a(3), b(3);
  a.shuffle(v);
  b.shuffle(w);
  CHECK(v == w);
  std::vector<int> sorted = v;
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < 100; ++i) CHECK(sorted[i] == i);
  CHECK_FALSE(std::is_sorted(v.begin(), v.end()));
}

TEST_CASE("mix64 separates nearby seeds", "[fuzz][rng]") {
  using dtlab::fuzz::mix64;
  CHECK(mix64(0) != mix64(1));
  CHECK((mix64(1) ^ mix64(2)) > (std::uint64_t{1} << 32));
}
