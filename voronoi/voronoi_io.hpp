#pragma once
// Voronoi cells out: one OBJ with a group per cell, a VTU of polyhedron cells
// (VTK_POLYHEDRON) for ParaView, and a JSON manifest.
#include <string>

#include <nlohmann/json.hpp>

#include "kernel/vtu_writer.hpp"
#include "voronoi/voronoi.hpp"

namespace dtlab {

void write_cells_obj(const std::string& path, const VoronoiDiagram& vd);
// VTK_POLYHEDRON cells (repeated sites' empty cells left out), in ascending vertex count
// (the order meshio needs to match cell data to its per-count blocks), with cell data `site`
// (the site's index), `volume`, `walls` (faces on the box) and `defect` (1: the cell
// fails voronoi/cell_check.hpp's check_cell at 1e-9 of the box diagonal).
void write_cells_vtu(const std::string& path, const VoronoiDiagram& vd, VtuFormat format = VtuFormat::binary);
// Every cell as tetrahedra (VTK_TETRA, each cell its own points): a fan from the cell's
// first vertex to the triangles of the faces without it (the cells are convex, so the fan
// covers the cell once), with cell data `site` and `cell_volume` (the cell's volume).
// VTK integrates tetrahedra by their determinants, while VTK 9.1 integrates a polyhedron
// through its own triangulation, which loses pieces of some convex cells (voronoi/README.md).
void write_cells_tets_vtu(const std::string& path, const VoronoiDiagram& vd, VtuFormat format = VtuFormat::binary);
// Per cell: site, volume, centroid, faces, neighbours; plus the box and totals.
nlohmann::json cells_manifest(const VoronoiDiagram& vd);

}  // namespace dtlab
