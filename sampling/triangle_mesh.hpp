#pragma once
// An indexed triangle mesh: the input of every sampler.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "predicates/point.hpp"
#include "sampling/box3.hpp"

namespace dtlab {

struct TriangleMesh {
  std::vector<Point3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;

  const Point3& corner(std::size_t t, int k) const { return vertices[triangles[t][k]]; }
  // (b - a) x (c - a): twice the area, pointing to the side from which a, b, c turn
  // counter-clockwise (outward for an outward-oriented mesh).
  Point3 area_normal(std::size_t t) const {
    const Point3& a = corner(t, 0);
    return cross(corner(t, 1) - a, corner(t, 2) - a);
  }
  // hypot: no square of a component overflows or underflows (a triangle of side 1e80
  // has an area of 1e160, whatever its components' squares).
  double triangle_area(std::size_t t) const {
    const Point3 n = area_normal(t);
    return 0.5 * std::hypot(n.x, n.y, n.z);
  }
};

Box3 bounding_box(const TriangleMesh& mesh);
double surface_area(const TriangleMesh& mesh);
// Signed volume by the divergence theorem: positive for a closed, outward-oriented mesh.
double signed_volume(const TriangleMesh& mesh);
// Connected components across shared edges (shells), each with only its own vertices.
std::vector<TriangleMesh> connected_shells(const TriangleMesh& mesh);

}  // namespace dtlab
