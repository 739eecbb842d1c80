#pragma once
// Tetrahedra files: TetGen .ele (with its .node) and ParaView .vtu.
//
// Orientation: TetGen writes every tet with orient3d(a,b,c,d) < 0 in Shewchuk's
// convention (d above the counter-clockwise triangle abc). dtlab keeps tets with
// orient3d > 0 in memory and swaps the first two vertices on the way in and out,
// so our .ele files read like TetGen's.
#include <span>
#include <string>

#include "kernel/tetrahedralization.hpp"
#include "kernel/vtu_writer.hpp"

namespace dtlab {

// Writes PREFIX.node and PREFIX.ele (0-based numbering), the text formatted on
// `threads` threads (0: all; kernel/record_writer.hpp).
void write_tetgen(const std::string& prefix, const Tetrahedralization& t, unsigned threads = 1);
void write_ele(const std::string& path, std::span<const Tet> tets, unsigned threads = 1);
// Reads PREFIX.node and PREFIX.ele; tets come back in dtlab's orientation
// (first two vertices swapped), whatever their actual sign: checking it is the
// checker's job.
Tetrahedralization read_tetgen(const std::string& prefix);
std::vector<Tet> read_ele(const std::string& path, int first_index, std::size_t point_count);
// VTK_TETRA cells with cell data `volume` (positive in dtlab's orientation) and
// `defect` (1: the tet is flat or inverted by the exact orientation test).
void write_vtu(const std::string& path, const Tetrahedralization& t, VtuFormat format = VtuFormat::binary);

}  // namespace dtlab
