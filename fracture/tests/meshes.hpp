#pragma once
// Closed meshes shared by the fracture tests: an axis-aligned box, the unit cube and a
// small bumpy torus (the pipeline's built-in shape at a coarse resolution).
#include <cstdint>

#include "sampling/bumpy_torus.hpp"
#include "sampling/triangle_mesh.hpp"

namespace dtlab::test {

// An axis-aligned box, outward-oriented (two triangles per face).
inline TriangleMesh box(Point3 lo, Point3 hi) {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k)
    m.vertices.push_back({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
  const std::uint32_t q[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (auto& f : q) {
    m.triangles.push_back({f[0], f[1], f[2]});
    m.triangles.push_back({f[0], f[2], f[3]});
  }
  return m;
}

inline TriangleMesh unit_cube() { return box({0, 0, 0}, {1, 1, 1}); }

inline TriangleMesh small_torus() {
  BumpyTorusParams bp;
  bp.nu = 48;
  bp.nv = 24;
  return make_bumpy_torus(bp);
}

}  // namespace dtlab::test
