#pragma once
// Sites and the box shared by the Voronoi checker's tests.
#include <vector>

#include "tests/support/random_points.hpp"
#include "voronoi/box.hpp"
#include "voronoi/voronoi.hpp"

namespace dtlab::test {

// n sites uniform in the unit cube, reproducible from the seed.
inline std::vector<Point3> random_sites(std::size_t n, std::uint64_t seed) { return uniform(n, seed, 0, 1); }

// The unit cube with a margin of 0.1: every cell is clipped, none is empty.
inline const vor::Box kBox{{-0.1, -0.1, -0.1}, {1.1, 1.1, 1.1}};

// Our cells of the sites in their default box, on one thread.
inline VoronoiDiagram cells_of(const std::vector<Point3>& sites) {
  VoronoiOptions o;
  o.threads = 1;
  return compute_voronoi(sites, o);
}

}  // namespace dtlab::test
