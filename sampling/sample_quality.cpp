#include "sampling/sample_quality.hpp"

#include "sampling/winding_number.hpp"

namespace dtlab {

OutsideStats count_outside(const Bvh& bvh, const std::vector<Point3>& points) {
  OutsideStats s;
  const std::vector<char> in = inside_flags_robust(bvh, points);
  s.checked = points.size();
  for (char f : in) s.outside += !f;
  return s;
}

}  // namespace dtlab
