#pragma once
// What a sampler should know about a mesh before trusting an inside test on it.
#include <cstdint>
#include <string>

#include "sampling/triangle_mesh.hpp"

namespace dtlab {

struct MeshReport {
  std::size_t vertices = 0, triangles = 0;
  std::size_t boundary_edges = 0;      // used by one triangle
  std::size_t nonmanifold_edges = 0;   // used by three or more
  std::size_t misoriented_edges = 0;   // used twice in the same direction
  std::size_t degenerate_triangles = 0;  // repeated index or zero area
  std::uint64_t self_intersections = 0;  // intersecting triangle pairs
  bool closed = false;       // every edge used exactly twice
  bool manifold = false;     // no edge used more than twice
  bool oriented = false;     // every interior edge used once in each direction
  bool overflow = false;     // area, volume or extent beyond a double: no sampler can work
  double area = 0, volume = 0;
  Box3 box;
};

// The self-intersection count uses naive orient3d (exact enough on generic meshes)
// while coordinates stay below 1e60; beyond, where its products overflow, adaptive.
MeshReport analyze_mesh(const TriangleMesh& mesh);

}  // namespace dtlab
