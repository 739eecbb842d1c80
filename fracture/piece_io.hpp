#pragma once
// Fracture output: pieces.obj (one group per piece, material "outer" for the mesh
// surface and "cut" for interior faces, with pieces.mtl), exploded.obj (every piece
// moved away from the mesh centre by `explode` times its centroid offset) and the
// manifest.json (per piece volume, centroid, interior area, neighbours).
#include <string>

#include <nlohmann/json.hpp>

#include "fracture/fracture.hpp"

namespace dtlab {

void write_pieces_obj(const std::string& path, const FractureResult& r, double explode = 0);
void write_pieces_mtl(const std::string& path);
nlohmann::json fracture_manifest(const FractureResult& r);

}  // namespace dtlab
