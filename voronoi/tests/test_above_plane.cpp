#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "voronoi/above_plane.hpp"

using namespace dtlab;

TEST_CASE("first_plane_exceeded: the scalar expression's answer for every count and on the tolerance") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int round = 0; round < 2000; ++round) {
    const std::size_t count = static_cast<std::size_t>(round % 13);
    std::vector<double> X(count), Y(count), Z(count);
    for (std::size_t i = 0; i < count; ++i) X[i] = u(rng), Y[i] = u(rng), Z[i] = u(rng);
    const Point3 n{u(rng), u(rng), u(rng)}, o{u(rng), u(rng), u(rng)};
    const auto dist = [&](std::size_t i) { return n.x * (X[i] - o.x) + n.y * (Y[i] - o.y) + n.z * (Z[i] - o.z); };
    // The tolerance at one point's own rounded distance (not above it) or just below it.
    double tol = 1;
    if (count > 0) {
      const std::size_t k = static_cast<std::size_t>(round / 13) % count;
      tol = round % 2 ? dist(k) : std::nextafter(dist(k), -INFINITY);
    }
    bool expected = false;
    for (std::size_t i = 0; i < count; ++i) expected |= dist(i) > tol;
    INFO("round " << round << ", count " << count);
    const FacePlane plane{n, o, tol};
    CHECK((first_plane_exceeded(X.data(), Y.data(), Z.data(), count, &plane, 1) == 0) == expected);
  }
}

TEST_CASE("first_plane_exceeded: the first of several planes that a point lies beyond") {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int round = 0; round < 500; ++round) {
    const std::size_t count = static_cast<std::size_t>(round % 13), planes = 1 + round % 7;
    std::vector<double> X(count), Y(count), Z(count);
    for (std::size_t i = 0; i < count; ++i) X[i] = u(rng), Y[i] = u(rng), Z[i] = u(rng);
    std::vector<FacePlane> pl(planes);
    for (auto& p : pl) p = {{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, 1.5 * (u(rng) + 1)};
    std::size_t expected = planes;
    for (std::size_t f = 0; f < planes && expected == planes; ++f)
      for (std::size_t i = 0; i < count; ++i)
        if (pl[f].n.x * (X[i] - pl[f].o.x) + pl[f].n.y * (Y[i] - pl[f].o.y) + pl[f].n.z * (Z[i] - pl[f].o.z) > pl[f].t)
          expected = f;
    INFO("round " << round);
    CHECK(first_plane_exceeded(X.data(), Y.data(), Z.data(), count, pl.data(), planes) == expected);
  }
}
