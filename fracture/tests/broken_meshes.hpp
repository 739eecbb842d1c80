#pragma once
// Small hand-made meshes shared by the repair and winding-solid tests (the box: meshes.hpp).
#include <cstdint>
#include <string>

#include "fracture/mesh_repair.hpp"
#include "fracture/tests/meshes.hpp"
#include "sampling/triangle_mesh.hpp"

namespace dtlab::test {

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
