// _core.oracle: `dtlab oracle` on a numpy array. Ours, CGAL and TetGen (through the
// oracle module's public functions) are built, checked exactly and compared pairwise
// canonically, with the CLI's rules for "ok".
#include <optional>

#include "kernel/build.hpp"
#include "oracle/cgal_oracle.hpp"
#include "oracle/check.hpp"
#include "oracle/compare.hpp"
#include "oracle/report_json.hpp"
#include "oracle/tetgen_oracle.hpp"
#include <pybind11/stl.h>

#include "python/src/bindings.hpp"
#include "python/src/json_to_python.hpp"
#include "python/src/kernel_options.hpp"
#include "python/src/numpy_io.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

struct Checked {
  OracleRun run;
  std::optional<CheckReport> report;  // absent when the oracle gave no answer
};

struct Pair {
  std::size_t i, j;
  Comparison c;
};

py::dict oracle(py::handle points, const std::vector<std::string>& against, const std::string& predicates,
                const std::string& perturb, const std::string& tetgen, double timeout) {
  for (const std::string& name : against)
    if (name != "cgal" && name != "tetgen")
      throw py::value_error("--against: unknown oracle '" + name + "' (cgal, tetgen)");
  // The CLI's `dtlab oracle` builds with the default options and these two choices.
  const KernelChoice k = kernel_choice(predicates, perturb, "infinite", "brio", BuildOptions{}.seed, 1e-12, "absolute");
  const DoubleArray pts_array = point_array(points, "points");
  const std::span<const Point3> pts = points_of(pts_array);
  if (pts.size() < 4) throw py::value_error("fewer than 4 points");

  std::vector<Checked> runs;
  std::vector<Pair> pairs;
  bool ok = false;
  std::vector<std::string> problems;
  std::optional<BuildFailure> failure;
  {
    py::gil_scoped_release nogil;
    const BuildResult built = build_delaunay(pts, k.predicates, BuildOptions{});
    failure = built.failure;
    OracleRun ours;
    ours.name = "dtlab";
    ours.mesh = built.mesh;
    ours.duplicates = built.duplicates;
    ours.seconds = built.stats.seconds;
    if (built.failure)
      ours.note = std::string("build failed: ") + failure_name(built.failure->kind) + " " + built.failure->detail;
    runs.push_back({std::move(ours), std::nullopt});
    for (const std::string& name : against) {
      if (name == "cgal") runs.push_back({cgal_delaunay(pts), std::nullopt});
      else runs.push_back({tetgen_delaunay(pts, {.binary = tetgen, .timeout_s = timeout}), std::nullopt});
    }
    for (Checked& c : runs)
      if (c.run.mesh) c.report = check_tetrahedralization(*c.run.mesh, {.duplicates = c.run.duplicates});
    for (std::size_t i = 0; i < runs.size(); ++i)
      for (std::size_t j = i + 1; j < runs.size(); ++j)
        if (runs[i].report && runs[j].report)
          pairs.push_back({i, j, compare_canonical(*runs[i].run.mesh, *runs[i].report, *runs[j].run.mesh,
                                                   *runs[j].report)});
    // Ours must be valid and agree with every valid answer; with sos, which is CGAL's
    // perturbation, its tets must equal CGAL's exactly.
    ok = runs[0].report && runs[0].report->ok() && !built.failure;
    for (const Pair& p : pairs) {
      if (p.i != 0 || !runs[p.j].report->ok()) continue;
      if (!p.c.agree()) ok = false, problems.push_back("differs from " + runs[p.j].run.name);
      if (k.predicates.perturb && runs[p.j].run.name == "cgal" && !p.c.tets_equal)
        ok = false, problems.push_back("tets differ from CGAL's although both use the sos perturbation");
    }
  }

  py::dict out;
  out["ok"] = ok;
  out["problems"] = problems;
  py::dict rd;
  for (const Checked& c : runs) {
    py::dict r;
    r["answered"] = c.run.mesh.has_value();
    r["note"] = c.run.note;
    r["seconds"] = c.run.seconds;
    r["duplicates"] = c.run.duplicates.size();
    r["tets"] = c.run.mesh ? py::object(to_numpy<std::uint32_t, 4>(std::vector<Tet>(c.run.mesh->tets))) : py::none();
    r["check"] = c.report ? json_to_python(to_json(*c.report)) : py::none();
    rd[py::str(c.run.name)] = r;
  }
  out["runs"] = rd;
  py::dict cd;
  for (const Pair& p : pairs) cd[py::str(runs[p.i].run.name + " vs " + runs[p.j].run.name)] = json_to_python(to_json(p.c));
  out["comparisons"] = cd;
  return out;
}

}  // namespace

void bind_oracle(py::module_& m) {
  m.def("oracle", &oracle, py::arg("points"), py::arg("against"), py::arg("predicates"), py::arg("perturb"),
        py::arg("tetgen"), py::arg("timeout"), "`dtlab oracle` on an array (see dtlab.oracle).");
}

}  // namespace dtlab::python
