#pragma once
// The inner loop of the convexity test (cell_check.hpp): the first face plane that some
// point of a cell lies beyond by more than the plane's tolerance.
#include <cstddef>

#include "predicates/vec3.hpp"

namespace dtlab {

// A plane of the convexity test: a point p lies beyond it when n . (p - o) > t.
struct FacePlane {
  Point3 n, o;
  double t;
};

// The first of planes[0..count) that some point p_i (i < points; p_i = (X[i], Y[i], Z[i]))
// lies beyond, or `count` when none: the products and sums of dot(n, p - o) in that order.
// Several points per instruction (SSE2, or AVX2 where the machine has it, chosen at run
// time), each rounded as the scalar expression: the same answer on every machine. One
// call per cell (a call per face cost more than its loop at 15 faces of 26 vertices).
std::size_t first_plane_exceeded(const double* X, const double* Y, const double* Z, std::size_t points,
                                 const FacePlane* planes, std::size_t count);

}  // namespace dtlab
