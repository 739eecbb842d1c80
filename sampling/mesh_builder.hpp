#pragma once
// Shared by the mesh readers: checks indices and splits polygons into fans.
#include <string>
#include <vector>

#include "kernel/input_error.hpp"
#include "sampling/triangle_mesh.hpp"

namespace dtlab::detail {

// Appends polygon `poly` (0-based indices) as a triangle fan; throws on a polygon
// with fewer than three corners or an index outside [0, vertex count).
inline void add_polygon(TriangleMesh& mesh, const std::vector<long>& poly, const std::string& path,
                        long line) {
  if (poly.size() < 3)
    throw InputError(path, line, "face with " + std::to_string(poly.size()) + " corner(s), need 3");
  for (long i : poly)
    if (i < 0 || i >= static_cast<long>(mesh.vertices.size()))
      throw InputError(path, line,
                       "vertex index " + std::to_string(i) + " out of range (mesh has " +
                           std::to_string(mesh.vertices.size()) + " vertices)");
  for (std::size_t k = 1; k + 1 < poly.size(); ++k)
    mesh.triangles.push_back({static_cast<std::uint32_t>(poly[0]), static_cast<std::uint32_t>(poly[k]),
                              static_cast<std::uint32_t>(poly[k + 1])});
}

}  // namespace dtlab::detail
