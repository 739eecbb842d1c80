#pragma once
// The inner loop of the convexity test (cell_check.hpp): whether some point of a cell
// lies beyond a face's plane by more than the tolerance.
#include <cstddef>

#include "predicates/vec3.hpp"

namespace dtlab {

// Whether n . (p_i - o) > tol for some i < count (p_i = (X[i], Y[i], Z[i])), the products
// and sums of dot(n, p - o) in that order. Several points per instruction (SSE2, or AVX2
// where the machine has it, chosen at run time), each rounded as the scalar expression:
// the same answer on every machine.
bool any_above_plane(const double* X, const double* Y, const double* Z, std::size_t count, const Point3& n,
                     const Point3& o, double tol);

}  // namespace dtlab
