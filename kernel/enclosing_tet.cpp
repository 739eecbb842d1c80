#include "kernel/enclosing_tet.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "predicates/exact.hpp"

namespace dtlab {

namespace {
bool finite(const Point3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
}  // namespace

EnclosingTet enclosing_tet(std::span<const Point3> input, double factor) {
  if (!(std::isfinite(factor) && factor > 0))
    throw std::invalid_argument("bigtet FACTOR must be finite and positive");
  Point3 lo = input.empty() ? Point3{0, 0, 0} : input[0], hi = lo;
  for (const Point3& p : input) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const Point3 c{lo.x / 2 + hi.x / 2, lo.y / 2 + hi.y / 2, lo.z / 2 + hi.z / 2};
  const double size = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-300});
  // The face x+y+z = -r of this tet touches the box corner (-h,-h,-h) when r = 3h
  // (h half the largest extent): factor 1 is the smallest tet containing the box.
  const double r = factor * 1.5 * size;
  EnclosingTet t;
  t.corners = {Point3{c.x + r, c.y + r, c.z + r}, Point3{c.x + r, c.y - r, c.z - r},
               Point3{c.x - r, c.y + r, c.z - r}, Point3{c.x - r, c.y - r, c.z + r}};
  for (const Point3& q : t.corners)
    if (!finite(q)) {
      t.defect = "the enclosing tetrahedron overflows: its corners are not finite";
      return t;
    }
  const ExactPredicates exact;
  auto& k = t.corners;
  const int s = exact.orient3d(k[0], k[1], k[2], k[3]);
  if (s == 0) {
    t.defect = "the enclosing tetrahedron is flat in double precision";
    return t;
  }
  if (s < 0) std::swap(k[0], k[1]);
  // Strictly inside: on the positive side of each face (the corner it replaces moved
  // to the point keeps the orientation positive).
  const auto inside = [&](const Point3& p) {
    for (int f = 0; f < 4; ++f) {
      std::array<Point3, 4> q = k;
      q[f] = p;
      if (exact.orient3d(q[0], q[1], q[2], q[3]) <= 0) return false;
    }
    return true;
  };
  // The 8 box corners inside prove it for every point (32 exact tests). Otherwise
  // (FACTOR < 1, or rounding) every point is tested.
  bool box_inside = true;
  for (int corner = 0; corner < 8 && box_inside; ++corner)
    box_inside = inside({corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z});
  if (box_inside) return t;
  for (std::size_t i = 0; i < input.size(); ++i)
    if (!inside(input[i])) {
      t.defect = "point " + std::to_string(i) + " is not strictly inside the enclosing tetrahedron";
      return t;
    }
  return t;
}

}  // namespace dtlab
