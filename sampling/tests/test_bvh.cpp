#include <catch2/catch.hpp>

#include <random>

#include "kernel/ids.hpp"
#include "sampling/bumpy_torus.hpp"
#include "sampling/bvh.hpp"

using namespace dtlab;

TEST_CASE("BVH closest point matches brute force on the bumpy torus") {
  const TriangleMesh m = make_bumpy_torus({.nu = 40, .nv = 20});
  const Bvh bvh(m);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-2, 2);
  for (int i = 0; i < 300; ++i) {
    const Point3 q{U(rng), U(rng), U(rng) * 0.5};
    double best = INFINITY;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      best = std::min(best, norm2(closest_on_triangle(q, m.corner(t, 0), m.corner(t, 1), m.corner(t, 2)).point - q));
    const ClosestHit h = bvh.closest_point(q);
    REQUIRE(h.triangle < m.triangles.size());
    CHECK(h.distance2 == Approx(best).epsilon(1e-12));
    CHECK(norm2(h.point - q) == Approx(h.distance2).epsilon(1e-12));
  }
}

TEST_CASE("BVH ray hits match brute force") {
  const TriangleMesh m = make_bumpy_torus({.nu = 40, .nv = 20});
  const Bvh bvh(m);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> U(-2, 2);
  std::size_t total = 0;
  for (int i = 0; i < 200; ++i) {
    const Point3 o{U(rng), U(rng), U(rng)}, d{U(rng), U(rng), U(rng)};
    std::vector<std::uint32_t> fast, slow;
    bvh.for_each_ray_hit(o, d, 1.0, [&](std::uint32_t t, double) { fast.push_back(t); });
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
      const double s = ray_triangle(o, d, m.corner(t, 0), m.corner(t, 1), m.corner(t, 2));
      if (s >= 0 && s <= 1) slow.push_back(t);
    }
    std::sort(fast.begin(), fast.end());
    CHECK(fast == slow);
    total += slow.size();
  }
  CHECK(total > 50);  // the rays do meet the torus
}

TEST_CASE("closest point on a triangle names the right feature") {
  const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  CHECK(closest_on_triangle({0.2, 0.2, 1}, a, b, c).feature == TriFeature::face);
  CHECK(closest_on_triangle({-1, -1, 0}, a, b, c).feature == TriFeature::vertex_a);
  CHECK(closest_on_triangle({2, -0.5, 0}, a, b, c).feature == TriFeature::vertex_b);
  CHECK(closest_on_triangle({0.5, -1, 0}, a, b, c).feature == TriFeature::edge_ab);
  CHECK(closest_on_triangle({1, 1, 0}, a, b, c).feature == TriFeature::edge_bc);
  CHECK(closest_on_triangle({-1, 0.5, 3}, a, b, c).feature == TriFeature::edge_ca);
  CHECK(closest_on_triangle({1, 1, 0}, a, b, c).point == Point3{0.5, 0.5, 0});
}

TEST_CASE("BVH on an empty mesh answers nothing") {
  const TriangleMesh m;
  const Bvh bvh(m);
  CHECK(bvh.closest_point({0, 0, 0}).triangle == kNone);
  int hits = 0;
  bvh.for_each_ray_hit({0, 0, 0}, {1, 0, 0}, 1, [&](std::uint32_t, double) { ++hits; });
  CHECK(hits == 0);
}
