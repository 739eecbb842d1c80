#include "sampling/morton_order.hpp"

#include <algorithm>
#include <numeric>

namespace dtlab {

namespace {
// Spreads the low 21 bits of v so that bit k lands on bit 3k.
std::uint64_t spread3(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffull;
  v = (v | v << 16) & 0x1f0000ff0000ffull;
  v = (v | v << 8) & 0x100f00f00f00f00full;
  v = (v | v << 4) & 0x10c30c30c30c30c3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}
}  // namespace

std::vector<std::uint32_t> morton_order(const std::vector<Point3>& points, const Box3& box) {
  const Point3 e = box.extent();
  auto cell = [](double v, double lo, double ex) {
    const double t = ex > 0 ? (v - lo) / ex : 0.0;
    return static_cast<std::uint64_t>(std::clamp(t, 0.0, 1.0) * 2097151.0);
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> key(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3& p = points[i];
    key[i] = {spread3(cell(p.x, box.lo.x, e.x)) | spread3(cell(p.y, box.lo.y, e.y)) << 1 |
                  spread3(cell(p.z, box.lo.z, e.z)) << 2,
              static_cast<std::uint32_t>(i)};
  }
  std::sort(key.begin(), key.end());
  std::vector<std::uint32_t> order(points.size());
  for (std::size_t i = 0; i < key.size(); ++i) order[i] = key[i].second;
  return order;
}

}  // namespace dtlab
