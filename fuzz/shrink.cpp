#include "fuzz/shrink.hpp"

#include <algorithm>
#include <utility>

namespace dtlab::fuzz {

ShrinkResult shrink_points(std::vector<Point3> points,
                           const std::function<bool(const std::vector<Point3>&)>& fails,
                           std::size_t budget, ShrinkPosition from, const std::function<bool()>& stop) {
  ShrinkResult r;
  std::size_t granularity = std::max<std::size_t>(from.granularity, 2);
  std::size_t first_chunk = from.chunk;
  const auto test = [&](const std::vector<Point3>& candidate) {
    ++r.tests;
    return fails(candidate);
  };
  const auto stopped = [&](std::size_t chunk) {
    r.points = std::move(points);
    r.position = {granularity, chunk};
    return r;
  };
  while (points.size() >= 2) {
    granularity = std::min(granularity, points.size());
    const std::size_t n = points.size();
    bool reduced = false;
    // Try each complement (drop one chunk); ddmin's subset step is the special case
    // granularity == 2, so complements alone already converge to 1-minimal.
    for (std::size_t c = std::exchange(first_chunk, 0); c < granularity; ++c) {
      if (r.tests >= budget || (stop && stop())) return stopped(c);
      const std::size_t lo = n * c / granularity, hi = n * (c + 1) / granularity;
      std::vector<Point3> rest;
      rest.reserve(n - (hi - lo));
      rest.insert(rest.end(), points.begin(), points.begin() + static_cast<std::ptrdiff_t>(lo));
      rest.insert(rest.end(), points.begin() + static_cast<std::ptrdiff_t>(hi), points.end());
      if (test(rest)) {
        points = std::move(rest);
        granularity = std::max<std::size_t>(granularity - 1, 2);
        reduced = true;
        break;
      }
      if (stop && stop()) return stopped(c);
    }
    if (reduced) continue;
    if (granularity >= points.size()) break;  // every single point is needed
    granularity = std::min(points.size(), granularity * 2);
  }
  r.minimal = true;
  r.position = {granularity, 0};
  r.points = std::move(points);
  return r;
}

}  // namespace dtlab::fuzz
