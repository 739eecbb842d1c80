#pragma once
// Tetrahedralized pieces for FEM: each piece's closed surface given to TetGen as a
// piecewise linear complex (`tetgen -pY`: a constrained Delaunay tetrahedralization that
// keeps the surface triangles as they are, Steiner points only inside), run as a child
// process (oracle/peers/child_process.hpp) under a time limit. The tets' exact volume is
// compared with the surface's (oracle/check/exact_volume.hpp): equal when the tets fill
// exactly the region the surface bounds.
#include <string>
#include <vector>

#include "fracture/fracture.hpp"
#include "kernel/tetrahedralization.hpp"

namespace dtlab {

struct TetgenRunOptions {
  std::string binary = "tetgen";
  double timeout_s = 120;  // per piece
};

struct PieceTets {
  std::vector<Point3> points;  // the surface's vertices first (bit for bit), then Steiner points
  std::vector<Tet> tets;       // dtlab's orientation, orient3d(a, b, c, d) > 0 (kernel/tet_io.hpp's read_ele)
  double volume = 0;           // the tets' exact volume, rounded
  double surface_volume = 0;   // the surface's exact volume, rounded
  bool exact_match = false;    // the two exact volumes are equal
  std::size_t steiner = 0;     // points TetGen added inside
};

// Throws std::runtime_error naming what went wrong (TetGen missing, failed, timed out,
// or its output unreadable or not a tetrahedralization of this surface).
PieceTets tetrahedralize_piece(const TriangleMesh& surface, const TetgenRunOptions& options = {});
// Every piece of r; a failure names the piece ("piece 7: tetgen ...").
std::vector<PieceTets> tetrahedralize_pieces(const FractureResult& r, const TetgenRunOptions& options = {});

}  // namespace dtlab
