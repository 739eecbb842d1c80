#pragma once
// Exact circumcentres in rationals (GMP), for the degenerate rings of the Voronoi
// checker: equality and collinearity of Voronoi vertices decided without rounding.
#include <array>
#include <span>

#include <gmpxx.h>

#include "predicates/point.hpp"

namespace dtlab {

using ExactPoint = std::array<mpq_class, 3>;

// The centre of the sphere through a, b, c, d (not coplanar: the caller checks).
ExactPoint exact_circumcentre(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

// True when all points lie on one line (or coincide); exact.
bool all_collinear(std::span<const ExactPoint* const> points);

}  // namespace dtlab
