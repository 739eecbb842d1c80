#pragma once
// What rounding to doubles may do to a cell: one ulp of the largest coordinate
// magnitude, and how far a closed cell's volume can move when every vertex moves by
// at most d. Shared by `dtlab voronoi`'s refusal (voronoi_range.hpp) and the exact
// Voronoi checker's ulp floor (voronoi_check/voronoi_check.hpp), so both apply one rule.
#include "voronoi/box.hpp"
#include "voronoi/voronoi.hpp"

namespace dtlab {

// How many ulps of the box's largest coordinate a vertex computed in doubles may be
// off, per coordinate, and still count as correctly computed: 0.5 for rounding the
// result once, the rest for a few roundings of a computation relative to the site (whose
// offsets are exact differences of nearby doubles). Measured on far_translate and
// kettner_grid (voronoi_check/README.md): our cells, voro++'s and CGAL's dual vertices.
inline constexpr double kRoundingUlps = 4;

// One ulp of the box's largest coordinate magnitude: the spacing of doubles there, so
// no vertex inside the box is rounded by more than half of it per coordinate.
double box_ulp(const vor::Box& box);
// The floor as a Euclidean distance: sqrt(3) kRoundingUlps box_ulp(box), how far a
// correctly computed vertex may lie from the exact one.
inline double rounding_floor_distance(const vor::Box& box) { return 1.7320508075688772 * kRoundingUlps * box_ulp(box); }

// A bound on |V(c') - V(c)| for the cell c' = c with every vertex moved by at most d
// (Euclidean), the volume taken as cell_volume takes it (each face fanned from its first
// corner). Moving the vertices along the straight path, dV/ds is at most d times the
// fan triangles' area (V's gradient at a vertex is a third of its triangles' vector
// areas when the surface is closed), and a triangle's area grows by at most
// s d (|e1| + |e2|) + 2 s^2 d^2 on the way (e1, e2 its edges from the fan corner), so
//   |dV| <= d * sum over triangles of (area + d (|e1| + |e2|) / 2 + 2 d^2 / 3).
// Valid for a closed, consistently oriented cell (check_cell_closed); c is the cell
// measured (either end of the path: the bound is symmetric). `surface`: the triangles'
// area (the cell's surface when its faces are planar and convex).
struct VolumeRoundingBound {
  double surface = 0, volume = 0;
};
VolumeRoundingBound volume_rounding_bound(const VoronoiCell& c, double d);

}  // namespace dtlab
