#pragma once
// Any tool's Voronoi cells, as the checker reads them: per cell the site it belongs
// to, its vertices, its faces (vertex loops) and per face the neighbouring site's id
// (>= 0) or a box wall (-1..-6: x-lo, x-hi, y-lo, y-hi, z-lo, z-hi, voro++'s
// numbering). The shape voro++, scipy's regions (after clipping) and our OBJ/JSON
// give. Stored in flat arrays; `cell(i)` is a view with the layout of VoronoiCell, so
// the cell checks of voronoi/cell_check.hpp apply to it.
#include <cstdint>
#include <span>
#include <vector>

#include "voronoi/voronoi.hpp"

namespace dtlab {

class ToolCells {
 public:
  // Throws std::invalid_argument ("cell of site S: ...") on neighbours not one per face,
  // a face with fewer than 3 corners, a corner out of range, offsets that do not start
  // at 0 or do not rise, a neighbour id below -6 (no site and no wall), or a non-finite
  // vertex.
  void add_cell(std::int64_t site, std::span<const Point3> vertices, std::span<const std::uint32_t> face_offsets,
                std::span<const std::uint32_t> face_vertices, std::span<const std::int32_t> face_neighbor);
  std::size_t size() const { return site_.size(); }
  std::int64_t site(std::size_t c) const { return site_[c]; }
  // Views valid while this object lives and no cell is added; volume and centroid
  // are measured from the vertices (a tool's own volume is not trusted).
  VoronoiCell cell(std::size_t c) const;
  // The same view without the volume (the checker measures it once).
  VoronoiCell view(std::size_t c) const;
  std::size_t face_count(std::size_t c) const { return fn_off_[c + 1] - fn_off_[c]; }
  // Removes cell c (mutation tests); later cells shift down.
  void erase(std::size_t c);

 private:
  std::vector<std::int64_t> site_;
  std::vector<std::size_t> v_off_{0}, fo_off_{0}, fv_off_{0}, fn_off_{0};
  std::vector<Point3> v_;
  std::vector<std::uint32_t> fo_, fv_;
  std::vector<std::int32_t> fn_;
};

// Our own cells as a tool's (repeated sites' empty cells left out).
ToolCells tool_cells_of(const VoronoiDiagram& diagram);

// Volume of a closed cell with outward counter-clockwise faces (cones from its
// first vertex); 0 for a cell without faces.
double cell_volume(const VoronoiCell& c);

}  // namespace dtlab
