#pragma once
// Triangle-mesh files: OFF, OBJ, PLY (ASCII, binary little and big endian) and STL
// (ASCII and binary). Polygons are split into triangle fans. Readers throw
// InputError(file, line, reason); line is 0 for defects in binary data.
#include <string>

#include "kernel/input_error.hpp"
#include "sampling/triangle_mesh.hpp"

namespace dtlab {

// Dispatches on the extension (case-insensitive): .off .obj .ply .stl.
TriangleMesh read_mesh(const std::string& path);
TriangleMesh read_off(const std::string& path);
TriangleMesh read_obj(const std::string& path);
TriangleMesh read_ply(const std::string& path);
TriangleMesh read_stl(const std::string& path);

void write_off(const std::string& path, const TriangleMesh& mesh);

}  // namespace dtlab
