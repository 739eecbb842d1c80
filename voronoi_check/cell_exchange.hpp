#pragma once
// The file a Voronoi peer writes its cells in (little-endian, this machine's doubles):
//   "DTLV", f64 seconds (the peer's own timing of its cells), u64 cell count, then per
//   cell: i64 site, u32 vertex count nv, u32 face count nf, u32 corner count nc,
//   nv x 3 f64 vertices, nf x i32 neighbour ids (site ids, -1..-6 the box walls),
//   nf x u32 face sizes, nc x u32 corners (indices into the cell's vertices).
// Written by the C++ helper (dtlab_voronoi_peer) and the Python adapters
// (voronoi_check/voronoi_peer.py); faces are turned outward by whoever writes.
#include <string>

#include "voronoi_check/tool_cells.hpp"

namespace dtlab {

struct PeerCells {
  double seconds = 0;
  ToolCells cells;
};

void write_peer_cells(const std::string& path, double seconds, const ToolCells& cells);
// Throws std::runtime_error on a short, malformed or inconsistent file.
PeerCells read_peer_cells(const std::string& path);

}  // namespace dtlab
