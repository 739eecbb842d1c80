#pragma once
// Z-order (Morton) of points in a box: neighbours in the order are neighbours in
// space, so queries run in this order reuse the BVH nodes already in cache (about
// 30% more inside queries per second on random box points).
#include <cstdint>
#include <vector>

#include "sampling/box3.hpp"
#include "sampling/parallel.hpp"

namespace dtlab {

// Indices of `points` sorted by the 63-bit Morton code of their cell in `box`
// (points outside the box are clamped to it); ties keep input order.
std::vector<std::uint32_t> morton_order(const std::vector<Point3>& points, const Box3& box);

// pred(points[i]) for every i, evaluated in parallel in Morton order; the answer
// depends on each point only, so it is the same for any number of threads.
template <class Pred>
std::vector<char> classify_points(const std::vector<Point3>& points, const Box3& box, Pred&& pred,
                                  std::size_t min_chunk = 512) {
  const std::vector<std::uint32_t> order = morton_order(points, box);
  std::vector<char> out(points.size());
  parallel_chunks(order.size(), [&](std::size_t b, std::size_t e) {
    for (std::size_t k = b; k < e; ++k) out[order[k]] = pred(points[order[k]]) ? 1 : 0;
  }, min_chunk);
  return out;
}

}  // namespace dtlab
