#pragma once
// The exact fallback of the clipping engine, for cells whose double clip was
// ambiguous (ConvexCell::ambiguous: a vertex within the band or its error bound of a
// plane).
//
// Every cell vertex is the meeting point of three planes (box walls and bisectors of
// the site s with a neighbour p: 2(p - s).(x - s) <= |p - s|^2), all with rational
// coefficients, since sites and box are doubles. Scaled by a power of two to integers
// (GMP), a vertex is kept as the homogeneous integer point (x : w) solving its three
// plane equations (the 4D cross product of their rows), and its side of a new plane
// a.x <= c is the exact sign of a.x - c w (w > 0). The topology is ConvexCell's, fed
// these signs (clip_signs); a new vertex is the meet of the clip plane and the two
// faces of the edge it cuts, so coordinates never grow with the number of clips. Only
// the output vertices are rounded (each within an ulp of the exact one).
#include <cstdint>
#include <span>

#include "voronoi/convex_cell.hpp"

namespace dtlab::vor {

// Recomputes `cell` as the box clipped by the bisectors of sites[i] and each of
// `neighbors` (in that order), exactly; vertices relative to sites[i], as
// compute_cell has them before translating. Throws std::runtime_error if two of the
// planes do not meet in a point (cannot happen for distinct sites and a proper box).
void exact_clip_cell(ConvexCell& cell, std::span<const Point3> sites, std::uint32_t i,
                     std::span<const std::uint32_t> neighbors, const Box& box);

}  // namespace dtlab::vor
