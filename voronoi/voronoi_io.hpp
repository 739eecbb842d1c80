#pragma once
// Voronoi cells out: one OBJ with a group per cell, a VTU of polyhedron cells
// (VTK_POLYHEDRON) for ParaView, and a JSON manifest.
#include <string>

#include <nlohmann/json.hpp>

#include "voronoi/voronoi.hpp"

namespace dtlab {

void write_cells_obj(const std::string& path, const VoronoiDiagram& vd);
void write_cells_vtu(const std::string& path, const VoronoiDiagram& vd);
// Per cell: site, volume, centroid, faces, neighbours; plus the box and totals.
nlohmann::json cells_manifest(const VoronoiDiagram& vd);

}  // namespace dtlab
