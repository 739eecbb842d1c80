#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>

#include "kernel/build_impl.hpp"
#include "kernel/spatial_order.hpp"
#include "tests/support/random_points.hpp"

using namespace dtlab;

TEST_CASE("hilbert index is a bijection on a small grid with unit steps") {
  for (int bits : {3, 5}) {
    std::set<std::uint64_t> keys;
    std::uint64_t last = 0;
    for (std::uint32_t x = 0; x < (1u << bits); ++x)
      for (std::uint32_t y = 0; y < (1u << bits); ++y)
        for (std::uint32_t z = 0; z < (1u << bits); ++z) {
          last = hilbert_index(x, y, z, bits);
          keys.insert(last);
          CHECK(last < (std::uint64_t(1) << (3 * bits)));
        }
    CHECK(keys.size() == (std::size_t(1) << (3 * bits)));
  }
  // On an 8^3 grid scaled to the top bits, consecutive keys are face neighbours.
  std::vector<std::pair<std::uint64_t, std::array<int, 3>>> cells;
  for (int x = 0; x < 8; ++x)
    for (int y = 0; y < 8; ++y)
      for (int z = 0; z < 8; ++z)
        cells.push_back({hilbert_index(std::uint32_t(x) << 18, std::uint32_t(y) << 18, std::uint32_t(z) << 18, 21), {x, y, z}});
  std::sort(cells.begin(), cells.end());
  std::set<std::uint64_t> keys;
  for (auto& c : cells) keys.insert(c.first);
  REQUIRE(keys.size() == 512);
  for (std::size_t i = 1; i < cells.size(); ++i) {
    const auto& a = cells[i - 1].second;
    const auto& b = cells[i].second;
    CHECK(std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) == 1);
  }
}

TEST_CASE("brio order is a permutation and deterministic per seed") {
  const std::vector<Point3> pts = test::uniform(5000, 3, 0, 1);
  auto a = brio_order(pts, 7), b = brio_order(pts, 7), c = brio_order(pts, 8);
  CHECK(a == b);
  CHECK(a != c);
  std::sort(a.begin(), a.end());
  for (std::uint32_t i = 0; i < a.size(); ++i) REQUIRE(a[i] == i);
}

TEST_CASE("brio order on threads is the serial one", "[threads]") {
  // 300 000 points: the last rounds (262 500 and 32 812 points) take the two-thread sort
  // (from 65 536 points), the smaller ones the serial one; a clustered copy adds equal keys.
  std::vector<Point3> pts = test::uniform(300000, 11, 0, 1);
  for (std::size_t i = 0; i < 2000; ++i) pts[i] = Point3{0.5 + 1e-9 * double(i % 37), 0.5, 0.5 + 1e-9 * double(i)};
  const std::vector<std::uint32_t> serial = brio_order(pts, 3);
  for (const unsigned threads : {2u, 3u, 8u}) {
    INFO("threads " << threads);
    const bool same = brio_order(pts, 3, threads) == serial;  // as a bool: Catch would print the arrays
    CHECK(same);
  }
}

TEST_CASE("the points' permutations into insertion order and back, on one and many threads", "[threads]") {
  // 100 000 points: more than one parallel chunk (2^15) per thread at 3 threads.
  const std::vector<Point3> input = test::uniform(100000, 5, 0, 1);
  std::vector<std::uint32_t> order(input.size());
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  for (unsigned threads : {1u, 2u, 3u, 8u}) {
    std::vector<Point3> pts = input;
    detail::to_insertion_order(pts, order, threads);
    REQUIRE(pts.size() == input.size());
    bool renumbered = true;
    for (std::size_t k = 0; k < pts.size(); ++k) renumbered = renumbered && pts[k] == input[order[k]];
    CHECK(renumbered);
    std::vector<std::uint32_t> consumed = order;
    detail::to_input_order(pts, consumed, threads);
    CHECK(pts == input);
  }
}
