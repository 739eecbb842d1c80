#pragma once
// One diagnosis of a triangle mesh, shared by `dtlab mesh check`, `sample` and
// `fracture`: the same counts, the same words, a few locations of each problem.
// Vertices with identical coordinates are merged first (and counted): the topology
// below is the topology of the geometry, not of the file's indices.
#include <cstdint>
#include <string>
#include <vector>

#include "sampling/mesh_magnitude.hpp"
#include "sampling/triangle_mesh.hpp"

namespace dtlab {

struct MeshReport {
  std::size_t vertices = 0, triangles = 0;  // as read
  std::size_t duplicate_vertices = 0;       // at the coordinates of an earlier vertex (merged)
  std::size_t degenerate_triangles = 0;     // a repeated corner or three collinear corners (exact)
  std::size_t boundary_edges = 0;           // used by one triangle
  std::size_t boundary_loops = 0;           // connected chains of boundary edges (holes)
  std::size_t nonmanifold_edges = 0;        // used by three or more triangles
  std::size_t nonmanifold_vertices = 0;     // triangles around them form more than one fan
  std::size_t misoriented_edges = 0;        // used twice in the same direction
  std::uint64_t self_intersections = 0;     // intersecting triangle pairs (adaptive-exact predicates)
  bool closed = false;    // every edge used exactly twice
  bool manifold = false;  // no edge used more than twice, one fan around every vertex
  bool oriented = false;  // every edge used twice is used once in each direction
  MeshMagnitude magnitude;  // area, volume or extent beyond a double, or below: no sampler can work
  // Shells inside another shell of the same orientation (a second cover of a volume:
  // an inner shell inside-out, or overlapping solids); checked for up to 64 shells.
  std::size_t nested_shells = 0;
  double area = 0, volume = 0;  // volume: signed (negative: oriented inward)
  Box3 box;
  // Up to `locations` points per problem (an edge's midpoint, a vertex, a triangle's centroid).
  std::vector<Point3> duplicate_at, degenerate_at, boundary_at, nonmanifold_at, misoriented_at, self_intersection_at;

  // Closed, manifold, oriented, no self-intersection, no degenerate triangle, nonzero
  // volume: what a boolean needs (an inward orientation is flipped by the user).
  bool solid() const;
  // Area and (closed) volume are doubles: magnitude_problem is empty.
  bool measurable() const;
  // One phrase per problem ("not closed: 12 boundary edges in 2 boundary loops, e.g. at
  // (0, 1, 2)"), solid-breaking problems first; duplicate vertices are listed too.
  std::vector<std::string> problems() const;
  // The problems that keep the mesh from being solid, joined by "; " (empty when solid).
  std::string why_not_solid() const;
  // "closed, manifold, oriented, 0 self-intersecting pairs, ..." on one line.
  std::string summary() const;
};

// `self_intersection_limit` stops the pair count there (0: count all).
MeshReport analyze_mesh(const TriangleMesh& mesh, std::size_t locations = 3, std::uint64_t self_intersection_limit = 0);

// For disjoint closed shells: 1 where the shell lies inside another shell of the same
// orientation (MeshReport::nested_shells counts them), else 0.
std::vector<char> nested_same_orientation(const std::vector<TriangleMesh>& shells);

}  // namespace dtlab
