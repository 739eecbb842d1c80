// _core.voronoi: Voronoi cells clipped to a box. Cell arrays are read-only numpy views
// of the diagram's own storage (no copy per cell); a capsule keeps that storage alive.
#include <memory>
#include <optional>

#include <pybind11/stl.h>

#include "python/src/bindings.hpp"
#include "python/src/numpy_io.hpp"
#include "python/src/progress_callback.hpp"
#include "voronoi/voronoi.hpp"
#include "voronoi/voronoi_range.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

py::dict voronoi(py::handle points, std::optional<std::vector<double>> box, double margin,
                 const std::string& predicates, unsigned threads) {
  const DoubleArray pts = point_array(points, "points");
  if (pts.shape(0) == 0) throw py::value_error("no points");
  VoronoiOptions o;
  o.margin = margin;
  o.threads = threads;
  if (predicates != "naive" && predicates != "epsilon" && predicates != "adaptive" && predicates != "exact")
    throw py::value_error("predicates: " + predicates + " not in {naive,epsilon,adaptive,exact}");
  o.predicates.backend = predicates;
  if (box) {
    const auto& b = *box;
    if (b.size() != 6 || !(b[0] < b[3] && b[1] < b[4] && b[2] < b[5]))
      throw py::value_error("box needs xmin ymin zmin xmax ymax zmax with min < max");
    o.box = vor::Box{{b[0], b[1], b[2]}, {b[3], b[4], b[5]}};
  }
  if (!(margin >= 0)) throw py::value_error("margin must be non-negative");
  const auto sites = points_of(pts);
  // The CLI's ranges (voronoi/voronoi_range.hpp): cells right in doubles, or refused.
  if (const auto refusal = voronoi_refusal(sites, o.box, margin, {.box = "box", .margin = "margin"}))
    throw py::value_error(refusal->reason);
  auto vd = std::make_shared<VoronoiDiagram>();
  std::optional<Progress> listener = python_progress(py::none());  // Ctrl-C during the Delaunay build
  {
    py::gil_scoped_release nogil;
    const ProgressScope scope(progress_pointer(listener));
    *vd = compute_voronoi(sites, o);
  }
  if (std::string why = lost_cells_problem(*vd); !why.empty()) throw py::value_error(why);
  // One owner for every view: the diagram (its cells' spans point into vd->storage).
  py::capsule owner(new std::shared_ptr<const VoronoiDiagram>(vd),
                    [](void* p) { delete static_cast<std::shared_ptr<const VoronoiDiagram>*>(p); });
  py::list cells;
  for (const VoronoiCell& c : vd->cells) {
    py::dict d;
    d["vertices"] = readonly_view<double, 3>(c.vertices.data(), c.vertices.size(), owner);
    d["face_offsets"] = readonly_view<std::uint32_t, 1>(c.face_offsets.data(), c.face_offsets.size(), owner);
    d["face_vertices"] = readonly_view<std::uint32_t, 1>(c.face_vertices.data(), c.face_vertices.size(), owner);
    d["face_neighbors"] = readonly_view<std::int32_t, 1>(c.face_neighbor.data(), c.face_neighbor.size(), owner);
    d["neighbors"] = to_numpy<std::uint32_t, 1>(c.neighbors());
    d["volume"] = c.volume;
    d["centroid"] = py::make_tuple(c.centroid.x, c.centroid.y, c.centroid.z);
    d["duplicate_of"] = c.duplicate_of;
    cells.append(d);
  }
  py::dict out;
  out["cells"] = cells;
  out["box"] = py::make_tuple(py::make_tuple(vd->box.lo.x, vd->box.lo.y, vd->box.lo.z),
                              py::make_tuple(vd->box.hi.x, vd->box.hi.y, vd->box.hi.z));
  out["tets"] = vd->tets;
  out["clipped"] = vd->clipped;
  out["box_clipped"] = vd->box_clipped;
  out["seconds_delaunay"] = vd->seconds_dt;
  out["seconds_cells"] = vd->seconds_cells;
  return out;
}

}  // namespace

void bind_voronoi(py::module_& m) {
  m.def("voronoi", &voronoi, py::arg("points"), py::arg("box"), py::arg("margin"), py::arg("predicates"),
        py::arg("threads"), "Voronoi cells clipped to a box (see dtlab.voronoi).");
}

}  // namespace dtlab::python
