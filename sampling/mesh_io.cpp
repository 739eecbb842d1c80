#include "sampling/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <memory>

#include "kernel/output_file.hpp"

namespace dtlab {

TriangleMesh read_mesh(const std::string& path) {
  const auto dot = path.rfind('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == "off") return read_off(path);
  if (ext == "obj") return read_obj(path);
  if (ext == "ply") return read_ply(path);
  if (ext == "stl") return read_stl(path);
  throw InputError(path, 0, "unknown mesh extension (expected .off, .obj, .ply or .stl)");
}

void write_off(const std::string& path, const TriangleMesh& mesh) {
  OutputFile f(path);
  std::fprintf(f.get(), "OFF\n%zu %zu 0\n", mesh.vertices.size(), mesh.triangles.size());
  for (const Point3& p : mesh.vertices) std::fprintf(f.get(), "%.17g %.17g %.17g\n", p.x, p.y, p.z);
  for (const auto& t : mesh.triangles) std::fprintf(f.get(), "3 %u %u %u\n", t[0], t[1], t[2]);
  f.close();
}

}  // namespace dtlab
