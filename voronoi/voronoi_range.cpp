#include "voronoi/voronoi_range.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "voronoi/rounding_bound.hpp"

namespace dtlab {

namespace {

std::string voronoi_sites_problem(std::span<const Point3> sites) {
  if (sites.empty()) return "";
  Point3 lo = sites[0], hi = sites[0];
  for (const Point3& p : sites) {
    if (!(std::abs(p.x) <= kCellCoordinateMax && std::abs(p.y) <= kCellCoordinateMax &&
          std::abs(p.z) <= kCellCoordinateMax))
      return "site coordinates beyond 1e100 in magnitude (their squares overflow a double): Voronoi cells are "
             "computed for |x| <= 1e100";
    lo = min3(lo, p);
    hi = max3(hi, p);
  }
  if (std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) < kCellExtentMin)
    return "sites span less than 1e-100: Voronoi cells need an extent of at least 1e-100";
  return "";
}

std::string voronoi_box_problem(const vor::Box& box, bool given, double margin, const BoxOptionNames& names) {
  for (double c : {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z})
    if (!(std::abs(c) <= kBoxCoordinateMax)) {
      char what[96];
      std::snprintf(what, sizeof what, " %g grows the sites' bounding box", margin);
      return (given ? std::string(names.box) + ": corners" : std::string(names.margin) + what) +
             " beyond 1e101 in magnitude (cell volumes overflow a double near 1e102): cells are computed in a box "
             "within |x| <= 1e101";
    }
  return "";
}

}  // namespace

std::optional<VoronoiRefusal> voronoi_refusal(std::span<const Point3> sites, const std::optional<vor::Box>& box,
                                              double margin, const BoxOptionNames& names) {
  if (std::string why = voronoi_sites_problem(sites); !why.empty())
    return VoronoiRefusal{VoronoiRefusal::Range::sites, std::move(why)};
  if (std::string why = voronoi_box_problem(box ? *box : default_box(sites, margin), box.has_value(), margin, names);
      !why.empty())
    return VoronoiRefusal{VoronoiRefusal::Range::box, std::move(why)};
  return std::nullopt;
}

std::string lost_cells_problem(const VoronoiDiagram& vd) {
  double sum = 0;
  for (std::size_t i = 0; i < vd.cells.size(); ++i) {
    const auto& c = vd.cells[i];
    if (c.duplicate_of >= 0) continue;
    if (!std::isfinite(c.volume) || c.volume < 0 || (c.volume == 0 && !vd.may_be_empty(i)))
      return "a Voronoi cell with no volume (zero or NaN): the sites are too close for cells in double precision";
    sum += c.volume;
  }
  const double error = std::abs(sum - vd.box.volume());
  if (error <= 1e-6 * vd.box.volume()) return "";
  // Where the box is a few ulps of its coordinates wide, correctly rounded vertices move
  // the volumes by more than 1e-6: the ulp floor of the exact Voronoi checker
  // (voronoi/rounding_bound.hpp) applies, the most kRoundingUlps ulps per vertex allow.
  if (!(error <= cells_rounding_floor(vd).volume))
    return "the cells do not fill the box (double precision lost on these sites)";
  return "";
}

CellsRoundingFloor cells_rounding_floor(const VoronoiDiagram& vd, bool with_volume) {
  CellsRoundingFloor f;
  f.vertex_error = rounding_floor_distance(vd.box);
  if (!with_volume) return f;
  for (const auto& c : vd.cells)
    if (c.duplicate_of < 0) f.volume += volume_rounding_bound(c, f.vertex_error).volume;
  return f;
}

}  // namespace dtlab
