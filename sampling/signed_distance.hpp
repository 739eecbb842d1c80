#pragma once
// Signed distance to a triangle mesh, the sign taken from the angle-weighted
// pseudonormal (Baerentzen and Aanaes 2005) of the feature holding the closest point:
// the face normal, the sum of the two face normals at an edge, or the sum of the face
// normals at a vertex weighted by their corner angles. Correct for closed, manifold,
// outward-oriented meshes; wrong near holes, which is what the experiments show.
#include <vector>

#include "sampling/bvh.hpp"

namespace dtlab {

class SignedDistance {
 public:
  explicit SignedDistance(const Bvh& bvh);
  // Negative inside.
  double operator()(const Point3& q) const;

 private:
  const Bvh& bvh_;
  std::vector<Point3> face_;    // unit face normals
  std::vector<Point3> edge_;    // 3 per triangle: edges ab, bc, ca
  std::vector<Point3> vertex_;  // angle-weighted
};

}  // namespace dtlab
