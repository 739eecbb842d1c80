#pragma once
// Pinched vertices (the triangles around a vertex form two or more fans: two lobes of a
// solid touching at a point, as the winding-number solid or a merged duplicate vertex
// leaves them) separated: one vertex per fan, each moved a little into its own fan.
#include <cstddef>

#include "sampling/triangle_mesh.hpp"

namespace dtlab {

// Merges vertices with identical coordinates, then gives every fan of a pinched vertex
// its own vertex, moved by `fraction` of the way to the mean of the fan's other corners
// (so the copies no longer coincide). Vertices on an edge used by more than two
// triangles are left alone. Returns the number of pinched vertices separated.
std::size_t separate_pinched_vertices(TriangleMesh& mesh, double fraction = 1e-3);

}  // namespace dtlab
