#pragma once
// Point sets of the experiments: every fuzz family by name, plus points sampled
// inside the built-in bumpy torus ("torus-rays": the thesis's ray-intersection
// sampler, "torus-sdf", "torus-winding": the robust one).
#include <cstdint>
#include <string>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::experiments {

// Throws std::invalid_argument for an unknown name. Mesh samplers may return a few
// points more or fewer than n (the ray method's stochastic rounding).
std::vector<Point3> experiment_points(const std::string& source, std::size_t n, std::uint64_t seed);

bool is_point_source(const std::string& source);

}  // namespace dtlab::experiments
