#include "python/src/triangle_mesh_arrays.hpp"

#include "python/src/numpy_io.hpp"

namespace py = pybind11;

namespace dtlab::python {

TriangleMesh mesh_from_arrays(py::handle vertices, py::handle faces) {
  TriangleMesh mesh;
  const DoubleArray v = point_array(vertices, "vertices");
  const auto p = points_of(v);
  mesh.vertices.assign(p.begin(), p.end());
  mesh.triangles = index_rows<3>(faces, mesh.vertices.size(), "faces");
  if (mesh.triangles.empty()) throw py::value_error("mesh has no triangles");
  return mesh;
}

py::tuple mesh_to_arrays(TriangleMesh&& mesh) {
  return py::make_tuple(points_to_numpy(std::move(mesh.vertices)),
                        to_numpy<std::uint32_t, 3>(std::move(mesh.triangles)));
}

}  // namespace dtlab::python
