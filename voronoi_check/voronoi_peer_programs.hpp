#pragma once
// The Voronoi peers the dtlab_voronoi_peer helper runs in its own process
// (voronoi_check/peer_voronoi_main.cpp): each takes the sites and the box and returns
// its cells clipped to the box. Refusals throw PeerRefusal, peers built without their
// library PeerNotInstalled (oracle/peers/peer_programs.hpp); crashes and hangs are not caught.
#include <chrono>
#include <vector>

#include "oracle/peers/peer_programs.hpp"
#include "voronoi_check/cell_exchange.hpp"

namespace dtlab {

PeerCells peer_voro(const std::vector<Point3>& sites, const vor::Box& box);
PeerCells peer_cgal_dual(const std::vector<Point3>& sites, const vor::Box& box);

// Adds a cell whose faces may turn inward (a tool's convention): when its volume is
// negative every face is reversed, so the cell's faces turn outward.
void add_outward_cell(ToolCells& cells, std::int64_t site, std::span<const Point3> vertices,
                      std::span<const std::uint32_t> offsets, std::vector<std::uint32_t>& corners,
                      std::span<const std::int32_t> neighbors);

}  // namespace dtlab
