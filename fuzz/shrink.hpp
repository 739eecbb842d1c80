#pragma once
// Delta debugging (Zeller and Hildebrandt's ddmin) over the points of a failing
// input: the result still fails and removing any single chunk at the final
// granularity no longer does (1-minimal when the budget allows).
#include <cstddef>
#include <functional>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::fuzz {

struct ShrinkResult {
  std::vector<Point3> points;
  std::size_t tests = 0;    // calls of the predicate
  bool minimal = false;     // 1-minimal (false: the budget ran out first)
};

// `fails(points)` must be true for `points`; it is called at most `budget` times.
ShrinkResult shrink_points(std::vector<Point3> points,
                           const std::function<bool(const std::vector<Point3>&)>& fails,
                           std::size_t budget = 2000);

}  // namespace dtlab::fuzz
