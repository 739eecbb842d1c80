#include <algorithm>

#include "voronoi_check/voronoi_peer_programs.hpp"

namespace dtlab {

void add_outward_cell(ToolCells& cells, std::int64_t site, std::span<const Point3> vertices,
                      std::span<const std::uint32_t> offsets, std::vector<std::uint32_t>& corners,
                      std::span<const std::int32_t> neighbors) {
  if (cell_volume(cell_view(vertices, offsets, corners, neighbors)) < 0)
    for (std::size_t f = 0; f + 1 < offsets.size(); ++f)
      std::reverse(corners.begin() + offsets[f], corners.begin() + offsets[f + 1]);
  cells.add_cell(site, vertices, offsets, corners, neighbors);
}

}  // namespace dtlab
