#pragma once
// Fracture output: pieces.obj (one group per piece, material "outer" for the mesh
// surface and "cut" for interior faces, with pieces.mtl), exploded.obj (every piece
// moved away from the mesh centre by `explode` times its centroid offset) and the
// manifest.json (the input's mesh report and repairs; per piece volume, centroid,
// inertia tensor, interior area, neighbours).
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fracture/fracture.hpp"
#include "fracture/piece_tets.hpp"
#include "fracture/volume_identity.hpp"
#include "kernel/vtu_writer.hpp"

namespace dtlab {

void write_pieces_obj(const std::string& path, const FractureResult& r, double explode = 0);
void write_pieces_mtl(const std::string& path);
// --split: DIR/piece_0000.obj ... one closed piece per file, groups outer / cut with
// materials from ../pieces.mtl (DIR is a subfolder of the output). `placed(path)` is
// called as each file is in place. Returns the file names.
std::vector<std::string> write_piece_files(const std::string& dir, const FractureResult& r,
                                           const std::function<void(const std::string& path)>& placed = {});
// "piece_0007.obj": the name of piece i's file in the --split folder.
std::string piece_file_name(std::size_t i);
// The piece files in DIR that a --split run may have written (regular files named as
// piece_file_name names them), as paths: an earlier run's set, removed before a new one is written.
std::vector<std::string> piece_files_in(const std::string& dir);
// Every piece as one VTK_POLYHEDRON cell (its triangles as faces) with cell data
// `piece`, `site` (the site's index among its level's sites), `parent` (-1 at the top
// level), `volume`, `interior_area`, `cut_triangles` and `boolean_skipped` (1: copied
// whole, its cell held it without a boolean).
void write_pieces_vtu(const std::string& path, const FractureResult& r, VtuFormat format = VtuFormat::binary);
// Every piece as its closed triangles (VTK_TRIANGLE cells, the piece's own points),
// with cell data `piece`, `site`, `island`, `cut` (1 on cut faces): the form VTK
// integrates correctly (vtkMassProperties per piece), unlike non-convex polyhedron cells.
void write_piece_surfaces_vtu(const std::string& path, const FractureResult& r, VtuFormat format = VtuFormat::binary);
// --tets: every piece's tets (VTK_TETRA, the piece's own points) with cell data
// `piece`, `site`, `island`; tets[i] belongs to r.pieces[i].
void write_piece_tets_vtu(const std::string& path, const FractureResult& r, const std::vector<PieceTets>& tets,
                          VtuFormat format = VtuFormat::binary);
// The manifest's `volume_identity`: both differences, relative, and whether the exact one is zero.
nlohmann::json volume_identity_json(const VolumeIdentity& id, double mesh_volume);
// Adds per piece `tets`, `steiner_points`, `tet_volume`, `tet_volume_exact` (the tets'
// exact volume equals the surface's) and the totals under `tets`.
void add_tets_to_manifest(nlohmann::json& manifest, const std::vector<PieceTets>& tets);
// `density` scales the per-piece `mass` and `mass_inertia` (inertia stays unit density).
nlohmann::json fracture_manifest(const FractureResult& r, double density = 1);

}  // namespace dtlab
