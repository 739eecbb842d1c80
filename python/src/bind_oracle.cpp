// _core.oracle: `dtlab oracle` on a numpy array, through the same library call as
// the CLI (oracle/oracle_session.hpp): the same peers, verdicts, comparisons and
// exit code. `functions`: {name: runner} of Python callables as peers (function_peers.hpp).
#include <stdexcept>

#include "oracle/child_process.hpp"
#include "oracle/oracle_session.hpp"
#include "oracle/report_json.hpp"
#include <pybind11/stl.h>

#include "python/src/bindings.hpp"
#include "python/src/function_peers.hpp"
#include "python/src/interrupt_check.hpp"
#include "python/src/json_to_python.hpp"
#include "python/src/kernel_options.hpp"
#include "python/src/numpy_io.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

py::dict oracle(py::handle points, const std::vector<std::string>& against, const std::string& predicates,
                const std::string& perturb, const std::string& boundary, const std::string& order, std::uint64_t seed,
                double eps, const std::string& eps_mode, const std::string& tetgen, double timeout, double memory_mb,
                const py::dict& functions) {
  // The same kernel options as `dtlab oracle` (and tetrahedralize()).
  const KernelChoice k = kernel_choice(predicates, perturb, boundary, order, seed, eps, eps_mode);
  if (!(timeout >= 0.001 && timeout <= 1e6)) throw py::value_error("--timeout: must be a number in [0.001, 1e6]");
  if (!(memory_mb >= 0 && memory_mb <= 1e9)) throw py::value_error("--memory: must be a number in [0, 1e9]");
  const FunctionPeers function_peers(functions);
  try {
    expand_peer_names(against);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("--against: ") + e.what());
  }
  const DoubleArray pts_array = point_array(points, "points");
  const std::span<const Point3> pts = points_of(pts_array);
  OracleSessionOptions o;
  o.against = against;
  o.predicates = k.predicates;
  o.build = k.build;
  o.peers.timeout_s = timeout;
  o.peers.memory_bytes = static_cast<std::uint64_t>(memory_mb * 1e6);
  o.peers.tetgen = tetgen;
  OracleSession s;
  bool interrupted = false;
  {
    const InterruptCheck check;
    py::gil_scoped_release nogil;
    try {
      s = run_oracle_session(pts, o);
    } catch (const ChildInterrupted&) {
      interrupted = true;  // the KeyboardInterrupt is pending, raised below
    } catch (const std::invalid_argument& e) {
      py::gil_scoped_acquire gil;
      throw py::value_error(e.what());
    }
  }
  if (interrupted) throw py::error_already_set();
  py::dict out(json_to_python(to_json(s)));
  out["dtlab_tets"] = to_numpy<std::uint32_t, 4>(std::vector<Tet>(s.built.mesh.tets));
  py::dict tets, checks;
  for (const PeerRun& p : s.peers) {
    tets[py::str(p.name)] = p.mesh ? py::object(to_numpy<std::uint32_t, 4>(std::vector<Tet>(p.mesh->tets))) : py::none();
    checks[py::str(p.name)] = p.report ? json_to_python(to_json(*p.report)) : py::none();
  }
  out["peer_tets"] = tets;
  out["peer_checks"] = checks;
  return out;
}

}  // namespace

void bind_oracle(py::module_& m) {
  m.def("oracle", &oracle, py::arg("points"), py::arg("against"), py::arg("predicates"), py::arg("perturb"),
        py::arg("boundary"), py::arg("order"), py::arg("seed"), py::arg("eps"), py::arg("eps_mode"), py::arg("tetgen"),
        py::arg("timeout"), py::arg("memory_mb"), py::arg("functions") = py::dict(),
        "`dtlab oracle` on an array (see dtlab.oracle).");
}

}  // namespace dtlab::python
