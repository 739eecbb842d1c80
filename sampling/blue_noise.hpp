#pragma once
// Weighted sample elimination (Yuksel 2015): from M candidates keep N with
// Poisson-disk-like spacing, by repeatedly removing the candidate whose neighbours
// crowd it most. Deterministic: ties break by index.
#include <vector>

#include "predicates/point.hpp"

namespace dtlab {

// `dim` is 2 for points on a surface of area `measure`, 3 for points in a volume of
// that measure; it sets the maximal Poisson-disk radius r_max of N points.
std::vector<Point3> eliminate_samples(const std::vector<Point3>& candidates, std::size_t target, int dim,
                                      double measure);

// Smallest distance between two distinct points (brute force over a grid): the
// Poisson-disk radius the set achieves.
double min_pair_distance(const std::vector<Point3>& points);

}  // namespace dtlab
