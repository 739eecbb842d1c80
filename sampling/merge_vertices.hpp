#pragma once
// Vertices with identical coordinates merged into one (exact comparison of doubles):
// the first step of every mesh diagnosis and repair.
#include <cstdint>
#include <vector>

#include "sampling/triangle_mesh.hpp"

namespace dtlab {

struct MergedMesh {
  TriangleMesh mesh;                    // unused vertices kept only if they were first
  std::vector<std::uint32_t> original;  // merged vertex -> first input vertex at its point
  std::size_t duplicates = 0;           // input vertices that were merged into an earlier one
  std::vector<Point3> duplicate_at;     // a few of their positions
};

// `keep_locations`: how many duplicate positions to record.
MergedMesh merge_duplicate_vertices(const TriangleMesh& mesh, std::size_t keep_locations = 3);

}  // namespace dtlab
