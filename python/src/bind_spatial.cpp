// _core.spatial_*: the topology dtlab.spatial (scipy-shaped Delaunay, ConvexHull,
// Voronoi) needs beyond the tets: neighbours, exact point location, cospherical and
// coplanar groups, Voronoi ridges (python/src/spatial_topology.hpp).
#include <string>
#include <utility>

#include "python/src/bindings.hpp"
#include "python/src/numpy_io.hpp"
#include "python/src/spatial_topology.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

using Int32Array = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>;

// Tets (m, 4) over `point_count` points, each with four distinct vertices.
std::vector<Tet> tet_rows(py::handle tets, std::size_t point_count) {
  std::vector<Tet> rows = index_rows<4>(tets, point_count, "tets");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Tet& k = rows[i];
    if (k[0] == k[1] || k[0] == k[2] || k[0] == k[3] || k[1] == k[2] || k[1] == k[3] || k[2] == k[3])
      throw py::value_error("tets[" + std::to_string(i) + "]: repeated vertex");
  }
  return rows;
}

// An (m, K) array of neighbour indices in [-1, m).
template <std::size_t K>
std::vector<std::array<std::int32_t, K>> neighbour_rows(py::handle obj, std::size_t m, const char* what) {
  const Int32Array a = Int32Array::ensure(obj);
  if (!a || a.ndim() != 2 || static_cast<std::size_t>(a.shape(0)) != m || a.shape(1) != static_cast<py::ssize_t>(K))
    throw py::value_error(std::string(what) + " must be an (" + std::to_string(m) + ", " + std::to_string(K) +
                          ") integer array");
  std::vector<std::array<std::int32_t, K>> rows(m);
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < K; ++j) {
      const std::int32_t v = a.data()[i * K + j];
      if (v < -1 || v >= static_cast<std::int64_t>(m)) throw py::value_error(std::string(what) + ": index out of range");
      rows[i][j] = v;
    }
  return rows;
}

py::array_t<std::int32_t> neighbors(py::handle tets, std::size_t point_count) {
  const std::vector<Tet> k = tet_rows(tets, point_count);
  TetNeighbors nb;
  {
    py::gil_scoped_release nogil;
    nb = tet_neighbors(k, point_count);
  }
  return to_numpy<std::int32_t, 4>(std::move(nb));
}

py::array_t<std::int32_t> locate(py::handle points, py::handle tets, py::handle nbs, py::handle queries) {
  const DoubleArray pts = point_array(points, "points");
  const DoubleArray q = point_array(queries, "xi");
  const std::vector<Tet> k = tet_rows(tets, pts.shape(0));
  const TetNeighbors nb = neighbour_rows<4>(nbs, k.size(), "neighbors");
  std::vector<std::int32_t> out;
  {
    py::gil_scoped_release nogil;
    out = locate_points(points_of(pts), k, nb, points_of(q));
  }
  return to_numpy<std::int32_t, 1>(std::move(out));
}

py::array_t<std::int32_t> cospherical(py::handle points, py::handle tets, py::handle nbs) {
  const DoubleArray pts = point_array(points, "points");
  const std::vector<Tet> k = tet_rows(tets, pts.shape(0));
  const TetNeighbors nb = neighbour_rows<4>(nbs, k.size(), "neighbors");
  std::vector<std::int32_t> g;
  {
    py::gil_scoped_release nogil;
    g = cospherical_groups(points_of(pts), k, nb);
  }
  return to_numpy<std::int32_t, 1>(std::move(g));
}

py::array_t<std::int32_t> coplanar(py::handle points, py::handle triangles, py::handle nbs) {
  const DoubleArray pts = point_array(points, "points");
  const auto tris = index_rows<3>(triangles, pts.shape(0), "triangles");
  const auto nb = neighbour_rows<3>(nbs, tris.size(), "triangle neighbors");
  return to_numpy<std::int32_t, 1>(coplanar_groups(points_of(pts), tris, nb));
}

py::dict ridges(py::handle tets, std::size_t point_count, py::handle nbs, py::handle groups) {
  const std::vector<Tet> k = tet_rows(tets, point_count);
  const TetNeighbors nb = neighbour_rows<4>(nbs, k.size(), "neighbors");
  const Int32Array g = Int32Array::ensure(groups);
  if (!g || g.ndim() != 1 || static_cast<std::size_t>(g.shape(0)) != k.size())
    throw py::value_error("groups must be one integer per tet");
  VoronoiRidges r;
  {
    py::gil_scoped_release nogil;
    r = voronoi_ridges(k, nb, {g.data(), k.size()});
  }
  py::dict out;
  out["points"] = to_numpy<std::uint32_t, 2>(std::move(r.points));
  out["offsets"] = to_numpy<std::int64_t, 1>(std::move(r.offsets));
  out["vertices"] = to_numpy<std::int32_t, 1>(std::move(r.vertices));
  return out;
}

}  // namespace

void bind_spatial(py::module_& m) {
  m.def("spatial_neighbors", &neighbors, py::arg("tets"), py::arg("point_count"),
        "Per tet, the tet across the facet opposite each vertex (-1 on the hull).");
  m.def("spatial_locate", &locate, py::arg("points"), py::arg("tets"), py::arg("neighbors"), py::arg("xi"),
        "Per query, a tet whose closed region holds it (-1 outside the hull): exact visibility walk.");
  m.def("spatial_cospherical_groups", &cospherical, py::arg("points"), py::arg("tets"), py::arg("neighbors"),
        "Per tet, its group of adjacent tets sharing one circumsphere (exact insphere = 0).");
  m.def("spatial_coplanar_groups", &coplanar, py::arg("points"), py::arg("triangles"), py::arg("neighbors"),
        "Per hull triangle, its group of adjacent triangles in one plane (exact orient3d = 0).");
  m.def("spatial_voronoi_ridges", &ridges, py::arg("tets"), py::arg("point_count"), py::arg("neighbors"),
        py::arg("groups"), "Voronoi ridges: point pairs, and the ridge vertices in cyclic order (-1: infinity).");
}

}  // namespace dtlab::python
