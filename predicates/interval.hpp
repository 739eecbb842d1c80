#pragma once
// `interval`: the naive determinants in interval arithmetic (Boost.Interval, directed
// rounding), and GMP (exact.hpp) when the interval contains zero. A dynamic filter,
// like CGAL's Filtered_predicate over Interval_nt, next to adaptive's semi-static one:
// both exact, the question is which costs less inside the same inserter.
#include <string_view>

#include "predicates/backend.hpp"

namespace dtlab {

// The sign when the interval decides it, else 0 and *decided = false.
int interval_orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d, bool* decided);
int interval_insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e,
                      bool* decided);

struct IntervalPredicates {
  static constexpr std::string_view name() { return "interval"; }
  int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const;
  int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) const;
};

static_assert(PredicateBackend<IntervalPredicates>);

}  // namespace dtlab
