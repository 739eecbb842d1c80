#pragma once
// How many sampled points lie outside the mesh, judged by the reference classifier
// (inside_flags_robust: strict tree winding number, exact sum near the threshold).
#include <cstddef>
#include <vector>

#include "sampling/bvh.hpp"

namespace dtlab {

struct OutsideStats {
  std::size_t checked = 0;
  std::size_t outside = 0;
  double fraction() const { return checked ? static_cast<double>(outside) / static_cast<double>(checked) : 0.0; }
};

OutsideStats count_outside(const Bvh& bvh, const std::vector<Point3>& points);

}  // namespace dtlab
