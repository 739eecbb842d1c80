#include <catch2/catch.hpp>

#include "sampling/blue_noise.hpp"
#include "sampling/bumpy_torus.hpp"
#include "sampling/mesh_sampler.hpp"
#include "sampling/sample_quality.hpp"

using namespace dtlab;

TEST_CASE("weighted sample elimination widens the minimum spacing for every method") {
  const TriangleMesh m = make_bumpy_torus({.nu = 48, .nv = 24});
  const MeshSampler s(m);
  for (SampleMethod method : {SampleMethod::surface, SampleMethod::rays, SampleMethod::sdf, SampleMethod::winding}) {
    INFO(method_name(method));
    SampleRequest r{.method = method, .count = 1000, .seed = 11};
    const auto plain = s.sample(r);
    r.blue_noise = true;
    const auto blue = s.sample(r);
    REQUIRE(blue.points.size() == 1000);
    const double d_plain = min_pair_distance(plain.points), d_blue = min_pair_distance(blue.points);
    CHECK(d_blue > 2 * d_plain);
    CHECK(blue.points == s.sample(r).points);  // reproducible
    if (method != SampleMethod::surface && method != SampleMethod::rays)
      CHECK(count_outside(s.bvh(), blue.points).outside == 0);
  }
}

TEST_CASE("elimination keeps a subset and handles trivial targets") {
  std::vector<Point3> p;
  for (int i = 0; i < 200; ++i) p.push_back({i * 0.01, (i * 37 % 200) * 0.01, (i * 91 % 200) * 0.01});
  const auto kept = eliminate_samples(p, 50, 3, 8.0);
  REQUIRE(kept.size() == 50);
  for (const Point3& q : kept) CHECK(std::find(p.begin(), p.end(), q) != p.end());
  CHECK(eliminate_samples(p, 500, 3, 8.0).size() == 200);
  CHECK(eliminate_samples(p, 0, 3, 8.0).empty());
}

TEST_CASE("min_pair_distance matches brute force") {
  std::vector<Point3> p;
  for (int i = 0; i < 300; ++i) p.push_back({std::sin(i * 1.7) * 3, std::cos(i * 0.3), std::sin(i * 0.11) * 0.5});
  double brute = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) brute = std::min(brute, norm(p[i] - p[j]));
  CHECK(min_pair_distance(p) == brute);
}
