#pragma once
// The pieces as glTF 2.0 (`fracture --gltf`), which Blender, Godot, Unity and three.js
// import: one .gltf (JSON) with its buffer embedded as a base64 data URI; one node and
// one mesh per piece (named piece_i), two primitives per mesh: the mesh's surface with
// material 0 ("outer") and the cut faces with material 1 ("cut"). Positions are
// float32 (glTF's only POSITION type) in the input's coordinates, unchanged (glTF
// calls +Y up: a z-up mesh lies on its side); no normals, so viewers shade flat.
#include <string>

#include <nlohmann/json.hpp>

#include "fracture/fracture.hpp"

namespace dtlab {

nlohmann::json pieces_gltf(const FractureResult& r);
// Throws (InputError naming the file) when it cannot be written.
void write_pieces_gltf(const std::string& path, const FractureResult& r);

}  // namespace dtlab
