#pragma once
// Named point sources shared by bench, experiment and demo: every fuzz family
// (uniform, clustered, lattice, cospherical, ...) and "mesh" (points sampled inside
// and on the built-in bumpy torus).
#include <cstdint>
#include <string>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::cli {

// Throws CLI::ValidationError for an unknown name.
std::vector<Point3> generate_points(const std::string& source, std::size_t n, std::uint64_t seed);

}  // namespace dtlab::cli
