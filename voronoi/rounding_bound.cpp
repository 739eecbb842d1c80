#include "voronoi/rounding_bound.hpp"

#include <algorithm>
#include <cmath>

namespace dtlab {

double box_ulp(const vor::Box& box) {
  double m = 0;
  for (double v : {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z}) m = std::max(m, std::abs(v));
  return std::nextafter(m, INFINITY) - m;
}

VolumeRoundingBound volume_rounding_bound(const VoronoiCell& c, double d) {
  double area = 0, edges = 0, triangles = 0;
  for (std::size_t f = 0; f < c.face_count(); ++f) {
    const auto b = c.face_offsets[f], e = c.face_offsets[f + 1];
    const Point3 o = c.vertices[c.face_vertices[b]];
    for (auto k = b + 1; k + 1 < e; ++k) {
      const Point3 e1 = c.vertices[c.face_vertices[k]] - o, e2 = c.vertices[c.face_vertices[k + 1]] - o;
      area += 0.5 * norm(cross(e1, e2));
      edges += norm(e1) + norm(e2);
      triangles += 1;
    }
  }
  // Computed in doubles: a relative 1e-12 more covers the sums' own rounding.
  return {area, d * (area + d * edges / 2 + 2 * d * d * triangles / 3) * (1 + 1e-12)};
}

}  // namespace dtlab
