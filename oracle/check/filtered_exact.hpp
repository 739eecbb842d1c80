#pragma once
// The checker's predicate backend: a static floating-point filter in front of the
// exact GMP predicates (predicates/exact.hpp). Independent of the adaptive backend
// on purpose, so that a bug there cannot hide a defect of a mesh it built.
//
// Filter: the determinant is evaluated in doubles with the same expression shape
// as Shewchuk's orient3d / insphere fast paths, and its sign is trusted when
// |det| > errbound * permanent, with Shewchuk's a-priori bounds (Shewchuk 1997,
// "Adaptive precision floating-point arithmetic and fast robust geometric
// predicates", section 4.3): orient3d (7 + 56 eps) eps, insphere (16 + 224 eps) eps,
// eps = 2^-53. Those bounds assume no underflow or overflow, so the filter also
// gives up (and the exact code answers) when the permanent is tiny, huge or not
// finite. The .cpp is compiled without FMA contraction.
#include <string_view>

#include "predicates/backend.hpp"

namespace dtlab {

struct FilteredExact {
  static constexpr std::string_view name() { return "filtered-exact"; }
  int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const;
  int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) const;
};

static_assert(PredicateBackend<FilteredExact>);

}  // namespace dtlab
