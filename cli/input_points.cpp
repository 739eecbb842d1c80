#include "cli/input_points.hpp"

#include <algorithm>
#include <cctype>

#include "sampling/mesh_io.hpp"

namespace dtlab::cli {

PointFile read_input_points(const std::string& path) {
  std::string ext = path.substr(path.find_last_of('.') == std::string::npos ? path.size() : path.find_last_of('.'));
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl") {
    PointFile f;
    f.points = read_mesh(path).vertices;
    return f;
  }
  return read_points(path);
}

}  // namespace dtlab::cli
