// _core.fuzz_families, _core.fuzz_generate, _core.fuzz_case_seed, _core.fuzz_case_points:
// the fuzz module's point-set registry, bit for bit what `dtlab fuzz` generates.
#include "fuzz/campaign.hpp"
#include "fuzz/case_seed.hpp"
#include "fuzz/families.hpp"
#include "python/src/bindings.hpp"
#include "python/src/numpy_io.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

py::list families() {
  py::list l;
  for (const fuzz::Family& f : fuzz::families()) l.append(py::make_tuple(f.name, f.description));
  return l;
}

py::array_t<double> generate(const std::string& family, std::size_t n, std::uint64_t seed) {
  const fuzz::Family* f = fuzz::find_family(family);
  if (!f) throw py::value_error("--family: unknown family '" + family + "' (see dtlab fuzz --list)");
  std::vector<Point3> points;
  {
    py::gil_scoped_release nogil;
    points = f->generate(n, seed);
  }
  return points_to_numpy(std::move(points));
}

}  // namespace

void bind_fuzz(py::module_& m) {
  m.def("fuzz_families", &families, "[(name, description)] of every point-set family.");
  m.def("fuzz_generate", &generate, py::arg("family"), py::arg("n"), py::arg("seed"),
        "n points of a family from a seed (see dtlab.fuzz.generate).");
  m.def("fuzz_case_seed", [](std::uint64_t seed, const std::string& family, std::uint64_t index) {
    return fuzz::case_seed(seed, family, index);
  }, py::arg("seed"), py::arg("family"), py::arg("index"), "The seed of case `index` of `family` in a campaign.");
  m.def("fuzz_case_points", &fuzz::case_points, py::arg("case_seed"), py::arg("min_points"), py::arg("max_points"),
        "The number of points of a campaign case, drawn from its seed.");
}

}  // namespace dtlab::python
