#pragma once
// Integer points on spheres and circles: the exact cospherical and cocircular
// configurations of the generators. Every coordinate is an integer well below
// 2^53, so it is exact in a double.
#include <cstdint>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::fuzz {

// All (x, y, z) in Z^3 with x^2 + y^2 + z^2 = r^2, in lexicographic order.
std::vector<Point3> sphere_lattice_points(std::int64_t r);

// The smallest r >= 1 whose sphere holds at least `count` lattice points.
std::int64_t sphere_radius_with(std::size_t count);

// All (x, y, 0) with x^2 + y^2 = m, in lexicographic order.
std::vector<Point3> circle_lattice_points(std::int64_t m);

// Squared radii m = 5*13*17*29*... (products of primes = 1 mod 4): x^2 + y^2 = m
// has 4 * 2^k solutions for k such primes, so these circles are rich in
// Pythagorean-type points. Increasing; the last has 1024 points.
const std::vector<std::int64_t>& rich_circle_radii2();

}  // namespace dtlab::fuzz
