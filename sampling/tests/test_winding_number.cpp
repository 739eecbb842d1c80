#include <catch2/catch.hpp>

#include <random>

#include "sampling/bumpy_torus.hpp"
#include "sampling/winding_number.hpp"

using namespace dtlab;

TEST_CASE("winding number is 1 inside and 0 outside the torus, exact and fast agree") {
  const TriangleMesh m = make_bumpy_torus({.nu = 48, .nv = 24});
  const Bvh bvh(m);
  const FastWindingNumber fast(bvh);
  // Points on the tube's core circle are inside; the centre and far points are outside.
  for (double u : {0.0, 1.0, 2.5, 4.0}) {
    const Point3 core{std::cos(u), std::sin(u), 0};
    CHECK(winding_number_exact(m, core) == Approx(1).margin(1e-9));
    CHECK(fast(core) == Approx(1).margin(0.02));
  }
  for (Point3 q : {Point3{0, 0, 0}, Point3{0, 0, 1}, Point3{3, 0, 0}, Point3{10, -7, 3}}) {
    CHECK(winding_number_exact(m, q) == Approx(0).margin(1e-9));
    CHECK(fast(q) == Approx(0).margin(0.02));
  }
}

TEST_CASE("fast winding number error shrinks with beta and with the first-order terms") {
  const TriangleMesh m = make_bumpy_torus({.nu = 48, .nv = 24});
  const Bvh bvh(m);
  auto worst_error = [&](double beta, int order, int* disagree) {
    const FastWindingNumber fast(bvh, beta, order);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> U(-1.6, 1.6);
    double worst = 0;
    for (int i = 0; i < 1000; ++i) {
      const Point3 q{U(rng), U(rng), U(rng) * 0.4};
      const double e = winding_number_exact(m, q), f = fast(q);
      worst = std::max(worst, std::abs(e - f));
      if (disagree) *disagree += (e > 0.5) != (f > 0.5);
    }
    return worst;
  };
  int disagree = 0;
  const double e2 = worst_error(2, 1, &disagree);
  CHECK(e2 < 0.03);
  CHECK(disagree == 0);
  CHECK(worst_error(4, 1, nullptr) < e2 / 3);
  CHECK(worst_error(2, 0, nullptr) > 2 * e2);
}

TEST_CASE("winding number is robust to holes: removing faces barely moves inside points") {
  TriangleMesh m = make_bumpy_torus({.nu = 48, .nv = 24});
  // Punch out every 7th triangle (about 14% of the faces).
  TriangleMesh holes = m;
  holes.triangles.clear();
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (t % 7 != 3) holes.triangles.push_back(m.triangles[t]);
  const Bvh bvh(holes);
  const FastWindingNumber fast(bvh);
  for (double u : {0.0, 1.0, 2.5, 4.0}) CHECK(fast({std::cos(u), std::sin(u), 0}) > 0.7);
  CHECK(std::abs(fast({0, 0, 0})) < 0.3);
  const std::vector<Point3> q = {{1, 0, 0}, {0, 0, 0}, {3, 0, 0}};
  CHECK(inside_flags(fast, q) == std::vector<char>{1, 0, 0});
  CHECK(inside_flags_robust(bvh, q) == std::vector<char>{1, 0, 0});
}

TEST_CASE("a mesh oriented inward throughout has winding number -1 inside, still classified inside") {
  TriangleMesh m = make_bumpy_torus({.nu = 32, .nv = 16});
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  const Bvh bvh(m);
  const FastWindingNumber fast(bvh);
  CHECK(winding_number_exact(m, {1, 0, 0}) == Approx(-1));
  CHECK(fast.inside({1, 0, 0}));
  CHECK_FALSE(fast.inside({0, 0, 0}));
  CHECK(inside_flags_robust(bvh, {{1, 0, 0}, {0, 0, 0}}) == std::vector<char>{1, 0});
}
