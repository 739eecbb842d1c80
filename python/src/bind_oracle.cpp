// _core.oracle: `dtlab oracle` on a numpy array, through the same library call as
// the CLI (oracle/oracle_session.hpp): the same peers, verdicts, comparisons and
// exit code. `functions`: {name: runner} of Python callables as peers (function_peers.hpp).
#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <future>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

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

// One oracle() call, shared by the caller and the worker thread that runs it. The
// caller waits without the GIL and checks Python's signals every 50 ms; on Ctrl-C it
// raises KeyboardInterrupt at once and leaves the worker to end alone. The build and
// the exact checks cannot stop midway: the worker finishes the stage it is in, its
// result discarded; a running peer is killed and no further stage starts.
struct OracleCall {
  std::vector<Point3> points;
  OracleSessionOptions options;
  OracleSession session;
  std::exception_ptr error;
  std::atomic<bool> cancelled{false};
  std::promise<void> done;
};

void run_call(const std::shared_ptr<OracleCall>& call) {
  // Signals go to Python's thread, which answers them.
  sigset_t block;
  sigemptyset(&block);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&block, sig);
  pthread_sigmask(SIG_BLOCK, &block, nullptr);
  t_cancelled = &call->cancelled;
  try {
    call->session = run_oracle_session(call->points, call->options);
  } catch (...) {
    call->error = std::current_exception();
  }
  call->done.set_value();
}

py::dict session_dict(const OracleSession& s);

// The session on the calling thread, the GIL released; Ctrl-C through InterruptCheck.
OracleSession run_here(std::span<const Point3> pts, const OracleSessionOptions& o) {
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
  return s;
}

py::dict oracle(py::handle points, const std::vector<std::string>& against, const std::string& predicates,
                const std::string& perturb, const std::string& boundary, const std::string& order,
                std::uint64_t seed, double eps, const std::string& eps_mode, const std::string& tetgen,
                double timeout, double memory_mb, const py::dict& functions) {
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
  // Python callables fork from the interpreter's own thread: the session runs here and
  // Ctrl-C is answered by the peer runner's polls (between stages and during peers).
  if (!function_peers.names().empty()) return session_dict(run_here(pts, o));
  auto call = std::make_shared<OracleCall>();
  call->points.assign(pts.begin(), pts.end());
  call->options = std::move(o);
  std::future<void> done = call->done.get_future();
  std::thread worker(run_call, call);
  bool interrupted = false;
  {
    py::gil_scoped_release nogil;
    while (done.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
      py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0) {
        interrupted = true;  // the KeyboardInterrupt is pending, raised below
        break;
      }
    }
  }
  if (interrupted) {
    call->cancelled = true;
    worker.detach();
    throw py::error_already_set();
  }
  worker.join();
  if (call->error) {
    try {
      std::rethrow_exception(call->error);
    } catch (const std::invalid_argument& e) {
      throw py::value_error(e.what());
    }
  }
  return session_dict(call->session);
}

py::dict session_dict(const OracleSession& s) {
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
  set_interrupt_check(&host_interrupt_requested);
  m.def("oracle", &oracle, py::arg("points"), py::arg("against"), py::arg("predicates"), py::arg("perturb"),
        py::arg("boundary"), py::arg("order"), py::arg("seed"), py::arg("eps"), py::arg("eps_mode"),
        py::arg("tetgen"), py::arg("timeout"), py::arg("memory_mb"), py::arg("functions") = py::dict(),
        "`dtlab oracle` on an array (see dtlab.oracle).");
}

}  // namespace dtlab::python
