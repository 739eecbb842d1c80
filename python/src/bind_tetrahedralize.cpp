// _core.tetrahedralize: the kernel's build_delaunay on a numpy array.
#include <optional>
#include <utility>

#include "kernel/build.hpp"
#include "options/tetra_summary.hpp"
#include "python/src/bindings.hpp"
#include "python/src/json_to_python.hpp"
#include "python/src/kernel_options.hpp"
#include "python/src/numpy_io.hpp"
#include "python/src/progress_callback.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

// {"tets", "duplicates", "skipped", "summary"}: summary is `dtlab tetra --json`'s.
py::dict tetrahedralize(py::handle points, const std::string& predicates, const std::string& perturb,
                        const std::string& boundary, const std::string& order, std::uint64_t seed, double eps,
                        const std::string& eps_mode, unsigned threads, const py::object& progress) {
  KernelChoice k = kernel_choice(predicates, perturb, boundary, order, seed, eps, eps_mode);
  k.build.threads = threads;  // 0: all hardware threads
  const DoubleArray pts = point_array(points, "points");
  std::optional<Progress> listener = python_progress(progress);
  BuildResult r;
  {
    py::gil_scoped_release nogil;
    const ProgressScope scope(progress_pointer(listener));
    r = build_delaunay(points_of(pts), k.predicates, k.build);
  }
  py::dict out;
  out["summary"] = json_to_python(tetra_summary(r, k.args));
  out["tets"] = to_numpy<std::uint32_t, 4>(std::move(r.mesh.tets));
  out["duplicates"] = to_numpy<std::uint32_t, 1>(std::move(r.duplicates));
  out["skipped"] = to_numpy<std::uint32_t, 1>(std::move(r.skipped));
  out["peak_tets"] = r.peak_tets;
  return out;
}

}  // namespace

void bind_tetrahedralize(py::module_& m) {
  m.def("tetrahedralize", &tetrahedralize, py::arg("points"), py::arg("predicates"), py::arg("perturb"),
        py::arg("boundary"), py::arg("order"), py::arg("seed"), py::arg("eps"), py::arg("eps_mode"),
        py::arg("threads") = 1u, py::arg("progress") = py::none(),
        "Builds the Delaunay tetrahedralization; returns the raw result (see dtlab.tetrahedralize).");
}

}  // namespace dtlab::python
