#pragma once
// The points a command reads: a point file (.node, .xyz) or the vertices of a mesh
// file (.off, .obj, .ply, .stl), as DESIGN.md's file formats promise.
#include <string>

#include "kernel/point_io.hpp"

namespace dtlab::cli {

PointFile read_input_points(const std::string& path);

// The help text of every INPUT read by read_input_points.
inline constexpr const char* kInputPointsHelp =
    "points: .node or .xyz, or the vertices of a mesh file (.off .obj .ply .stl)";

}  // namespace dtlab::cli
