#pragma once
// The topology dtlab.spatial (scipy-shaped Delaunay, ConvexHull, Voronoi) reads off a
// finished tetrahedralization: facet neighbours, point location by a visibility walk,
// groups of tets sharing one circumsphere (or hull triangles one plane), and the
// Voronoi ridges around every Delaunay edge. Every sign is exact (adaptive predicates).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/tetrahedralization.hpp"

namespace dtlab::python {

// nb[t][f]: the tet across the facet opposite vertex f of t, -1 on the hull.
using TetNeighbors = std::vector<std::array<std::int32_t, 4>>;
TetNeighbors tet_neighbors(std::span<const Tet> tets, std::size_t point_count);

// The tet whose closed region holds q (a point on a shared facet, edge or vertex gets
// one of its tets), or -1 when q is outside the convex hull. Tets have orient3d > 0.
// The walk starts at `start` (any tet) and falls back to a scan when it runs too long.
std::int32_t locate_point(std::span<const Point3> pts, std::span<const Tet> tets, const TetNeighbors& nb,
                          const Point3& q, std::int32_t start, std::uint64_t& rng);

// locate_point for every query, visited along a Hilbert curve over their bounding box so
// that each walk starts at the previous answer, close by.
std::vector<std::int32_t> locate_points(std::span<const Point3> pts, std::span<const Tet> tets,
                                        const TetNeighbors& nb, std::span<const Point3> queries);

// Tets sharing one circumsphere (insphere of a neighbour's apex exactly 0): the cells of
// the Delaunay complex, one Voronoi vertex each.
std::vector<std::int32_t> cospherical_groups(std::span<const Point3> pts, std::span<const Tet> tets,
                                             const TetNeighbors& nb);

// Hull triangles (outward, counter-clockwise) in one plane, adjacent across edges:
// tnb[i][j] is the triangle across the edge opposite corner j.
std::vector<std::int32_t> coplanar_groups(std::span<const Point3> pts,
                                          std::span<const std::array<std::uint32_t, 3>> tris,
                                          const std::vector<std::array<std::int32_t, 3>>& tnb);

// One Voronoi ridge per Delaunay-complex edge (a, b), a < b: the Voronoi vertices (tet
// groups) around the edge in cyclic order, -1 once for an unbounded ridge. A ridge needs
// three vertices, -1 included (as Qhull's): edges inside one cell of cospherical points
// and unbounded ridges with one finite vertex are left out.
struct VoronoiRidges {
  std::vector<std::array<std::uint32_t, 2>> points;
  std::vector<std::int64_t> offsets{0};  // ridge r is vertices[offsets[r] .. offsets[r + 1])
  std::vector<std::int32_t> vertices;
};
VoronoiRidges voronoi_ridges(std::span<const Tet> tets, const TetNeighbors& nb, std::span<const std::int32_t> group);

}  // namespace dtlab::python
