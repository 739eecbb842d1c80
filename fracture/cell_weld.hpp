#pragma once
// Shared cell corners made bit-identical. A Voronoi vertex is one point of several
// cells, but cells clipped in their site's frame ((v - s) + s) carry it a few ulps
// apart, so neighbouring cells overlap or gap by slivers and the pieces cannot tile
// the mesh exactly. Corners of different cells within `tolerance` (absolute) take
// the value of the lowest-numbered cell's; a cluster holding two corners of one cell
// is left alone (welding it would collapse an edge).
#include "fracture/anisotropic_cells.hpp"

namespace dtlab {

// Copies the cells' vertices into cells.vertices (if they are not there yet) and welds
// them. Returns the number of corners moved.
std::size_t weld_shared_corners(ScaledCells& cells, double tolerance);

}  // namespace dtlab
