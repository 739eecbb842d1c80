#include "sampling/triangle_mesh.hpp"

namespace dtlab {

Box3 bounding_box(const TriangleMesh& mesh) {
  Box3 b;
  for (const auto& t : mesh.triangles)
    for (auto v : t) b.add(mesh.vertices[v]);
  return b;
}

double surface_area(const TriangleMesh& mesh) {
  double a = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) a += mesh.triangle_area(t);
  return a;
}

double signed_volume(const TriangleMesh& mesh) {
  // Sum of signed tetrahedra (origin shifted to the box centre for accuracy).
  const Point3 o = bounding_box(mesh).center();
  double v = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    v += dot(mesh.corner(t, 0) - o, cross(mesh.corner(t, 1) - o, mesh.corner(t, 2) - o));
  return v / 6.0;
}

}  // namespace dtlab
