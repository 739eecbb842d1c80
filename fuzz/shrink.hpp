#pragma once
// Delta debugging (Zeller and Hildebrandt's ddmin) over the points of a failing
// input: the result still fails and removing any single chunk at the final
// granularity no longer does (1-minimal when the budget allows).
#include <cstddef>
#include <functional>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::fuzz {

// Where ddmin is: the granularity and the next chunk to drop. A stopped shrink
// resumes there.
struct ShrinkPosition {
  std::size_t granularity = 2, chunk = 0;
  auto operator<=>(const ShrinkPosition&) const = default;
};

struct ShrinkResult {
  std::vector<Point3> points;
  std::size_t tests = 0;    // calls of the predicate
  bool minimal = false;     // 1-minimal (false: the budget ran out first)
  ShrinkPosition position;  // where it stopped (a later call can resume there)
};

// `fails(points)` must be true for `points`; it is called at most `budget` times, and
// not once `stop()` (when given) says so; a try that fails not and is followed by a
// stop is tried again on resuming (the stop may have cut it short). `from`: where to
// start (a previous result's position, to go on from its points).
ShrinkResult shrink_points(std::vector<Point3> points,
                           const std::function<bool(const std::vector<Point3>&)>& fails,
                           std::size_t budget = 2000, ShrinkPosition from = {},
                           const std::function<bool()>& stop = {});

}  // namespace dtlab::fuzz
