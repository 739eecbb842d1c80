#pragma once
// Where double-precision Voronoi cells can be right, shared by `dtlab voronoi` and
// Python's dtlab.voronoi. The cells are clipped in doubles: squared distances of
// coordinates beyond 1e100 or below 1e-100 overflow or underflow, and so do cell
// volumes (cubes of the box's extent) near 1e102. Sites are computed for |x| <= 1e100,
// boxes (default: the sites' bounding box grown by the margin) for |x| <= 1e101.
// Each function returns the reason (none: "" or nullopt), for the caller to raise in
// its own style.
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "voronoi/voronoi.hpp"

namespace dtlab {

inline constexpr double kCellCoordinateMax = 1e100, kBoxCoordinateMax = 1e101, kCellExtentMin = 1e-100;

// Why a Voronoi run is refused before its cells, and which range refused it (the CLI
// reports bad sites as bad input, a box out of range as bad usage).
struct VoronoiRefusal {
  enum class Range { sites, box } range;
  std::string reason;
};

// How the caller names the box and the margin in its messages (Python: box=, margin=).
struct BoxOptionNames {
  std::string_view box = "--box", margin = "--margin";
};

// The sites' range (beyond 1e100 in magnitude, or spanning less than 1e-100), then the
// clip box's (a corner beyond 1e101): `box`, or if none the sites' bounding box grown
// by `margin` (default_box); nothing when both are in range.
std::optional<VoronoiRefusal> voronoi_refusal(std::span<const Point3> sites, const std::optional<vor::Box>& box,
                                              double margin, const BoxOptionNames& names = {});

// After the cells: computed cells that are no result: a cell of NaN, infinite or zero
// volume, or cells that do not fill the box (double precision lost on these sites):
// their volumes' sum off by more than 1e-6 of the box volume and by more than moving
// every vertex by kRoundingUlps ulps of the box's largest coordinate could explain
// (volume_rounding_bound, the exact Voronoi checker's ulp floor).
std::string lost_cells_problem(const VoronoiDiagram& vd);

// The ulp floor of a diagram's cells: `vertex_error` e = sqrt(3) kRoundingUlps ulps of the
// box's largest coordinate (how far a correctly computed vertex may be, Euclidean), and
// `volume` the most the cells' volume sum can move when every vertex moves by e (the sum
// of volume_rounding_bound over the cells that are not duplicates).
struct CellsRoundingFloor {
  double vertex_error = 0, volume = 0;
};
// with_volume false: the vertex bound only (the volume is a pass over every cell).
CellsRoundingFloor cells_rounding_floor(const VoronoiDiagram& vd, bool with_volume = true);

}  // namespace dtlab
