#pragma once
// --boundary bigtet: the thesis's big enclosing tetrahedron, a regular tet around the
// input's bounding box, and the exact proof that it holds every input point.
#include <array>
#include <span>
#include <string>

#include "predicates/point.hpp"

namespace dtlab {

struct EnclosingTet {
  std::array<Point3, 4> corners{};  // orient3d(corners) > 0 when valid
  std::string defect;               // empty when valid: finite, not flat, every point strictly inside
  bool valid() const { return defect.empty(); }
};

// FACTOR scales the tet (1: the smallest one holding the bounding box). The result is
// proven with exact predicates: corners finite, orient3d != 0, and the 8 corners of
// the bounding box (so, the tet being convex, every point) strictly inside. Throws
// std::invalid_argument on a FACTOR that is not finite and positive.
EnclosingTet enclosing_tet(std::span<const Point3> points, double factor);

}  // namespace dtlab
