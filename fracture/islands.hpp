#pragma once
// Islands: a Voronoi cell that crosses a thin part of a non-convex mesh meets it in
// several disconnected chunks. Each chunk (a connected component through shared
// edges, with any cavity shell it encloses) becomes a piece of its own, and the cut
// faces that pointed at a neighbouring site are re-pointed at the neighbour's island
// that lies across them.
#include <cstdint>
#include <vector>

#include "fracture/cell_boolean.hpp"

namespace dtlab {

// The islands of one closed piece, largest volume first. A shell of negative volume
// (a cavity) goes with the smallest positive shell enclosing it (exact winding number
// of that shell at one of the cavity's vertices). One island: the piece unchanged.
std::vector<PieceMesh> split_islands(const PieceMesh& piece);

// One island of a level: its site and its place among that site's islands.
struct IslandRef {
  std::size_t site = 0;
  std::size_t island = 0;
};

// `islands[k]` is island `refs[k]`; its cut_tag values name neighbour *sites*. Rewrites
// them to name neighbour *islands* (indices into `islands`): a cut triangle of site i
// facing site j goes to the island of j whose cut triangles facing i come closest to
// its centroid (the two sides of one bisector patch coincide, or lie a gap apart).
// A tag of a site without islands becomes -1.
void retag_to_islands(std::vector<PieceMesh>& islands, const std::vector<IslandRef>& refs, std::size_t sites);

}  // namespace dtlab
