#pragma once
// Point-set files: TetGen .node and plain .xyz in, .node and .xyz out.
// Readers throw InputError naming the file, the line and the reason.
#include <string>
#include <vector>

#include "kernel/input_error.hpp"
#include "predicates/point.hpp"

namespace dtlab {

struct PointFile {
  std::vector<Point3> points;
  int first_index = 0;  // .node numbering base (0 or 1); 0 for .xyz
};

// Dispatches on the extension: .node or .xyz (anything else is an InputError).
PointFile read_points(const std::string& path);
PointFile read_node(const std::string& path);
PointFile read_xyz(const std::string& path);

void write_node(const std::string& path, const std::vector<Point3>& points);
void write_xyz(const std::string& path, const std::vector<Point3>& points);

}  // namespace dtlab
