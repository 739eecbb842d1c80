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

// Dispatches on the extension, in any case: .node, or .xyz / .pwn / .txt (anything
// else is an InputError). An .xyz line is x y z, then optionally numeric attributes
// (CGAL's .xyz and .pwn carry normals: x y z nx ny nz), as many on every line; only
// x y z are read, the attributes are checked to be numbers.
PointFile read_points(const std::string& path);
PointFile read_node(const std::string& path);
PointFile read_xyz(const std::string& path);

// Coordinates in the shortest form that reads back to the same double; the text is
// formatted on `threads` threads (0: all), the bytes the same for any count.
void write_node(const std::string& path, const std::vector<Point3>& points, unsigned threads = 1);
void write_xyz(const std::string& path, const std::vector<Point3>& points, unsigned threads = 1);

}  // namespace dtlab
