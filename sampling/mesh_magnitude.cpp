#include "sampling/mesh_magnitude.hpp"

#include <algorithm>
#include <cfloat>

namespace dtlab {

namespace {

// Below the normal doubles (or 0) where the mesh scaled by a power of two (exactly)
// to a unit extent has a nonzero measure `scaled` of dimension `dim`.
bool underflows(double value, double scaled, int dim, int k) {
  return std::abs(value) < DBL_MIN && scaled != 0 && std::abs(std::ldexp(scaled, -dim * k)) < DBL_MIN;
}

}  // namespace

MeshMagnitude measure_magnitude(const TriangleMesh& mesh, double area, double volume) {
  MeshMagnitude m;
  const Box3 box = bounding_box(mesh);
  const Point3 ext = box.extent();
  m.overflow = !std::isfinite(area) || !std::isfinite(volume) || !std::isfinite(ext.x) || !std::isfinite(ext.y) ||
               !std::isfinite(ext.z);
  const double e = std::max({ext.x, ext.y, ext.z});
  if (m.overflow || !(e > 0) || (std::abs(area) >= DBL_MIN && std::abs(volume) >= DBL_MIN)) return m;
  const int k = -std::ilogb(e);  // e * 2^k in [1, 2)
  TriangleMesh unit = mesh;
  const Point3 c = box.center();
  for (Point3& p : unit.vertices) p = {std::ldexp(p.x - c.x, k), std::ldexp(p.y - c.y, k), std::ldexp(p.z - c.z, k)};
  m.area_underflow = underflows(area, surface_area(unit), 2, k);
  m.volume_underflow = underflows(volume, signed_volume(unit), 3, k);
  return m;
}

std::string magnitude_problem(const MeshMagnitude& m, bool surface_only) {
  if (m.overflow) return "coordinates too large: the area or volume overflows a double";
  if (m.area_underflow || (!surface_only && m.volume_underflow))
    return "coordinates too small: the area or volume underflows a double";
  return "";
}

}  // namespace dtlab
