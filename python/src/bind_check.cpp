// _core.check and _core.compare: the exact checker and the canonical comparison on
// numpy arrays, with any tool's tet orientation (python/src/orientation.hpp).
#include <algorithm>
#include <optional>
#include <utility>

#include "oracle/check/check.hpp"
#include "oracle/check/compare.hpp"
#include "oracle/check/report_json.hpp"
#include "python/src/bindings.hpp"
#include "python/src/json_to_python.hpp"
#include "python/src/numpy_io.hpp"
#include "python/src/orientation.hpp"
#include "python/src/progress_callback.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

std::vector<Point3> input_points(py::handle points) {
  const DoubleArray a = point_array(points, "points");
  const auto p = points_of(a);
  if (p.size() < 4) throw py::value_error("fewer than 4 points");
  return {p.begin(), p.end()};
}

struct Checked {
  Orientation orientation;
  CheckReport report;
};

// Orients t by `mode` and checks it; call without the GIL.
Checked check_oriented(Tetrahedralization& t, const std::string& mode, const CheckOptions& options) {
  Checked c;
  c.orientation = orient_tets(t, mode);
  c.report = check_tetrahedralization(t, options);
  return c;
}

py::dict report_dict(const Checked& c) {
  py::dict d = json_to_python(to_json(c.report));
  d["orientation"] = c.orientation.handedness;
  d["swapped"] = c.orientation.swapped;
  return d;
}

py::dict check(py::handle points, py::handle tets, const std::string& orientation, py::handle duplicates,
               std::size_t witnesses, bool delaunay, unsigned threads, const py::object& progress) {
  check_orientation_mode(orientation);
  Tetrahedralization t;
  t.points = input_points(points);
  t.tets = index_rows<4>(tets, t.points.size(), "tets");
  std::vector<std::uint32_t> dups;
  if (!duplicates.is_none()) dups = index_list(duplicates, t.points.size(), "duplicates");
  std::optional<Progress> listener = python_progress(progress);
  Checked c;
  {
    py::gil_scoped_release nogil;
    const ProgressScope scope(progress_pointer(listener));
    // t is ours: the owning check renumbers it for locality (the report keeps the caller's ids).
    c.orientation = orient_tets(t, orientation);
    c.report = check_tetrahedralization(std::move(t), {.duplicates = dups, .delaunay = delaunay,
                                                       .witnesses_per_kind = witnesses, .threads = threads});
  }
  return report_dict(c);
}

std::vector<Tet> sorted_tets(std::vector<Tet> tets) {
  for (Tet& k : tets) std::sort(k.begin(), k.end());
  std::sort(tets.begin(), tets.end());
  return tets;
}

// {"a", "b": check reports, "tets_equal": same vertex quadruples, "comparison": the
// canonical comparison (None unless both are valid)}.
py::dict compare(py::handle points, py::handle tets_a, py::handle tets_b, const std::string& orientation) {
  check_orientation_mode(orientation);
  Tetrahedralization a, b;
  a.points = input_points(points);
  a.tets = index_rows<4>(tets_a, a.points.size(), "tets_a");
  b.points = a.points;
  b.tets = index_rows<4>(tets_b, b.points.size(), "tets_b");
  Checked ca, cb;
  std::optional<Comparison> cmp;
  bool tets_equal = false;
  {
    py::gil_scoped_release nogil;
    ca = check_oriented(a, orientation, {});
    cb = check_oriented(b, orientation, {});
    if (ca.report.ok() && cb.report.ok()) cmp = compare_canonical(a, ca.report, b, cb.report);
    tets_equal = sorted_tets(a.tets) == sorted_tets(b.tets);
  }
  py::dict d;
  d["a"] = report_dict(ca);
  d["b"] = report_dict(cb);
  d["tets_equal"] = cmp ? cmp->tets_equal : tets_equal;
  d["comparison"] = cmp ? json_to_python(to_json(*cmp)) : py::none();
  return d;
}

py::list defect_kinds() {
  py::list l;
  for (int k = 0; k < kDefectKinds; ++k) l.append(defect_name(static_cast<DefectKind>(k)));
  return l;
}

}  // namespace

void bind_check(py::module_& m) {
  m.def("check", &check, py::arg("points"), py::arg("tets"), py::arg("orientation"), py::arg("duplicates"),
        py::arg("witnesses"), py::arg("delaunay"), py::arg("threads"), py::arg("progress") = py::none(),
        "Exact invariant check; returns the raw report (see dtlab.check).");
  m.def("compare", &compare, py::arg("points"), py::arg("tets_a"), py::arg("tets_b"), py::arg("orientation"),
        "Checks both meshes and compares them canonically (see dtlab.compare).");
  m.def("defect_kinds", &defect_kinds, "The checker's defect kinds, in its order.");
}

}  // namespace dtlab::python
