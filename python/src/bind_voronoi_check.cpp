// _core.check_voronoi: any tool's cells judged by the exact Voronoi checker
// (voronoi_check/voronoi_check.hpp); _core.default_box: the box dtlab's cells use.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <string>

#include "python/src/bindings.hpp"
#include "python/src/json_to_python.hpp"
#include "python/src/numpy_io.hpp"
#include "voronoi_check/check_json.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

template <class T>
std::vector<T> vector_of(py::handle h, const char* what) {
  const auto a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(h);
  if (!a || a.ndim() != 1) throw py::value_error(std::string(what) + ": a 1-d integer array expected");
  return std::vector<T>(a.data(), a.data() + a.size());
}

// cells: a list of (site, vertices (n, 3), face_offsets, face_vertices, face_neighbors);
// what add_cell refuses is named by the cell's index, as dtlab._tool_cells names the rest.
ToolCells tool_cells(py::handle cells) {
  ToolCells t;
  std::size_t k = 0;
  for (py::handle c : cells) {
    const py::tuple tu = py::reinterpret_borrow<py::tuple>(c);
    if (tu.size() != 5) throw py::value_error("a cell is (site, vertices, face_offsets, face_vertices, face_neighbors)");
    const DoubleArray v = point_array(tu[1], "cell vertices");
    try {
      t.add_cell(tu[0].cast<std::int64_t>(), points_of(v), vector_of<std::uint32_t>(tu[2], "face_offsets"),
                 vector_of<std::uint32_t>(tu[3], "face_vertices"), vector_of<std::int32_t>(tu[4], "face_neighbors"));
    } catch (const std::invalid_argument& e) {
      throw py::value_error("cells[" + std::to_string(k) + "]: " + e.what());
    }
    ++k;
  }
  return t;
}

py::object check_voronoi(py::handle points, py::handle cells, const std::vector<double>& b, double small_face,
                         double vertex_tolerance, double volume_tolerance, double ulps, unsigned threads) {
  const DoubleArray pts = point_array(points, "points");
  if (b.size() != 6) throw py::value_error("box: xmin ymin zmin xmax ymax zmax");
  const ToolCells t = tool_cells(cells);
  VoronoiCheckOptions o;
  o.small_face = small_face;
  o.vertex_tolerance = vertex_tolerance;
  o.volume_tolerance = volume_tolerance;
  o.ulps = ulps;
  o.threads = threads;
  VoronoiCheckReport r;
  try {
    py::gil_scoped_release nogil;
    r = check_voronoi(points_of(pts), vor::Box{{b[0], b[1], b[2]}, {b[3], b[4], b[5]}}, t, o);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  return json_to_python(to_json(r));
}

std::vector<double> box_of(py::handle points, double margin) {
  const DoubleArray pts = point_array(points, "points");
  if (pts.shape(0) == 0) throw py::value_error("no points");
  const vor::Box b = default_box(points_of(pts), margin);
  return {b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z};
}

}  // namespace

void bind_voronoi_check(py::module_& m) {
  m.def("check_voronoi", &check_voronoi, py::arg("points"), py::arg("cells"), py::arg("box"), py::arg("small_face"),
        py::arg("vertex_tolerance"), py::arg("volume_tolerance"), py::arg("ulps"), py::arg("threads"),
        "Judge Voronoi cells (see dtlab.check_voronoi).");
  m.def("default_box", &box_of, py::arg("points"), py::arg("margin"), "The bounding box grown by margin per side.");
}

}  // namespace dtlab::python
