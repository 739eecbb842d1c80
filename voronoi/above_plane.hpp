#pragma once
// The inner loop of the convexity test (cell_check.hpp): whether some point of a cell
// lies beyond a face's plane by more than the tolerance.
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

// Whether some point lies beyond one plane (first_plane_exceeded with that plane).
inline bool any_above_plane(const double* X, const double* Y, const double* Z, std::size_t count, const Point3& n,
                            const Point3& o, double tol) {
  const FacePlane plane{n, o, tol};
  return first_plane_exceeded(X, Y, Z, count, &plane, 1) == 0;
}

}  // namespace dtlab
