#pragma once
// Where double-precision Voronoi cells can be right, shared by `dtlab voronoi` and
// Python's dtlab.voronoi. The cells are clipped in doubles: squared distances of
// coordinates beyond 1e100 or below 1e-100 overflow or underflow, and so do cell
// volumes (cubes of the box's extent) near 1e102. Sites are computed for |x| <= 1e100,
// boxes (default: the sites' bounding box grown by the margin) for |x| <= 1e101.
// Each function returns "" or the reason, for the caller to raise in its own style.
#include <span>
#include <string>

#include "voronoi/voronoi.hpp"

namespace dtlab {

inline constexpr double kCellCoordinateMax = 1e100, kBoxCoordinateMax = 1e101, kCellExtentMin = 1e-100;

// Sites beyond 1e100 in magnitude or spanning less than 1e-100.
std::string voronoi_sites_problem(std::span<const Point3> sites);

// A clip box with a corner beyond 1e101 (`given`: --box, else grown by `margin`).
std::string voronoi_box_problem(const vor::Box& box, bool given, double margin);

// Computed cells that are no result: a cell of NaN, infinite or zero volume, or cells
// that do not fill the box (double precision lost on these sites).
std::string lost_cells_problem(const VoronoiDiagram& vd);

}  // namespace dtlab
