#pragma once
// Small hand-made meshes shared by the repair and winding-solid tests.
#include <cstdint>
#include <string>

#include "fracture/mesh_repair.hpp"
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

// Both meshes in one, sharing no vertex.
inline TriangleMesh join(TriangleMesh a, const TriangleMesh& b) {
  const auto n = static_cast<std::uint32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) a.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  return a;
}

// How many changes the repair step named `what` made (0 when it did not run).
inline std::size_t count_of(const RepairResult& r, const std::string& what) {
  for (const auto& s : r.steps)
    if (s.what == what) return s.count;
  return 0;
}

}  // namespace dtlab::test
