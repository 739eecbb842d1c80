#pragma once
// The cells a Voronoi command peer writes (voronoi_peer_command.hpp), read strictly:
//
// JSON ({out}.json), the shape voro++ and scipy users build:
//   {"cells": [{"site": i, "vertices": [[x, y, z], ...], "faces": [[v0, v1, v2, ...], ...],
//               "neighbors": [j, ...]}, ...], "seconds": s}
//   site: the site's id (0-based, as in {in}); faces: loops of indices into the cell's
//   vertices, in either orientation; neighbors: one per face, the neighbouring site's
//   id or -1..-6 for the box walls x-lo, x-hi, y-lo, y-hi, z-lo, z-hi (voro++'s
//   numbering); "seconds" (optional): the peer's own timing of its cells; a cell's
//   "volume" (optional) is ignored (the checker measures). Other fields are refused.
//
// voro++'s command-line output ({out}.vol, `voro++ -c "%i %w %P %s %n %t" ...`): one
// line per cell, "id nv (x,y,z)... nf n_1 .. n_nf (a,b,c,...)...".
//
// Either file is parsed as it is read (the JSON tree from the stream, a .vol file one
// line at a time), so garbage is refused at its first bad byte and no copy of the whole
// text is held. Faces are turned outward one by one (each against the mean of its cell's vertices,
// inside a convex cell), so a tool may write them in any orientation. Errors are
// std::runtime_error "FILE: cells[3].faces[1][2]: reason" (JSON path) or "FILE:LINE:
// reason"; never a crash, whatever the file holds.
#include <string>

#include "voronoi_check/cell_exchange.hpp"

namespace dtlab {

PeerCells read_cells_json(const std::string& path);
PeerCells read_cells_vol(const std::string& path);

}  // namespace dtlab
