#pragma once
// A convex polytope under construction, in growable arrays that a worker reuses from
// cell to cell (no allocation per cell once warm); the finished cell is copied into a
// CellArena. Faces are counter-clockwise seen from outside.
#include <cstdint>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::vor {

struct CellBuffer {
  std::vector<Point3> vertices;
  std::vector<std::uint32_t> face_offsets{0};  // face f: face_vertices[off[f] .. off[f+1])
  std::vector<std::uint32_t> face_vertices;
  std::vector<std::int32_t> face_neighbor;     // site id, or -1..-6 for the box walls
};

}  // namespace dtlab::vor
