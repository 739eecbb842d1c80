// _core.oracle: `dtlab oracle` on a numpy array, through the same library call as
// the CLI (oracle/peers/oracle_session.hpp): the same peers, verdicts, comparisons and
// exit code. `functions`: {name: runner} of Python callables as peers (function_peers.hpp);
// `progress`: None or progress(done, total, stage), called on the calling thread.
#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <pybind11/stl.h>
#include "oracle/check/report_json.hpp"
#include "oracle/peers/child_process.hpp"
#include "oracle/peers/oracle_session.hpp"

#include "kernel/exit_guard.hpp"
#include "python/src/bindings.hpp"
#include "python/src/function_peers.hpp"
#include "python/src/interrupt_check.hpp"
#include "python/src/json_to_python.hpp"
#include "python/src/kernel_options.hpp"
#include "python/src/numpy_io.hpp"
#include "python/src/progress_callback.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

// Progress events of a call on a worker thread, queued for the Python thread that waits
// for it: the callable runs there, with the GIL.
class ProgressQueue {
 public:
  struct Event {
    std::size_t done, total;
    std::string stage;
  };
  void push(const ProgressEvent& e) {
    const std::lock_guard<std::mutex> g(lock_);
    events_.push_back({e.done, e.total, std::string(e.stage)});
  }
  std::vector<Event> take() {
    const std::lock_guard<std::mutex> g(lock_);
    return std::exchange(events_, {});
  }

 private:
  std::mutex lock_;
  std::vector<Event> events_;
};

// The session's peer hooks as progress events: "NAME: running" as a peer starts and
// "NAME: VERDICT" once it is judged, done = the peers finished, of all. (Our build,
// "insert", and our check, "check", reach the thread's listener by themselves.)
void report_peers(OracleSessionOptions& o, const std::function<void(const ProgressEvent&)>& emit) {
  o.progress = [emit](const std::string& name, std::size_t done, std::size_t total) {
    const std::string stage = name + ": running";
    emit(ProgressEvent{stage, done, total});
  };
  o.on_peer = [emit](const PeerRun& run, std::size_t done, std::size_t total) {
    const std::string stage = run.name + ": " + verdict_name(run.verdict);
    emit(ProgressEvent{stage, done, total});
  };
}

// One oracle() call, shared by the caller and the worker thread that runs it. The
// caller waits without the GIL and, every 50 ms, checks Python's signals and hands the
// queued progress to the callable; on Ctrl-C (or an exception of the callable) it
// cancels the worker, gives it half a second to end (a running peer is killed, the
// build stops at its next progress step) and raises, leaving a worker still in a
// check to end alone, its result discarded.
struct OracleCall {
  std::vector<Point3> points;
  OracleSessionOptions options;
  OracleSession session;
  std::exception_ptr error;
  std::atomic<bool> cancelled{false};
  bool report = false;  // queue progress events
  ProgressQueue events;
  std::promise<void> done;
};

void run_call(const std::shared_ptr<OracleCall>& call) {
  // Signals go to Python's thread, which answers them.
  sigset_t block;
  sigemptyset(&block);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&block, sig);
  pthread_sigmask(SIG_BLOCK, &block, nullptr);
  t_cancelled = &call->cancelled;
  OracleCall& c = *call;
  const std::function<void(const ProgressEvent&)> emit = [&c](const ProgressEvent& e) {
    if (c.cancelled) throw ChildInterrupted();
    if (c.report) c.events.push(e);
  };
  Progress listener(emit);
  const ProgressScope scope(&listener);
  report_peers(c.options, emit);
  try {
    c.session = run_oracle_session(c.points, c.options);
  } catch (...) {
    c.error = std::current_exception();
  }
  c.done.set_value();
}

// Waits for the worker (see OracleCall). False when the caller gives up: Ctrl-C, or
// the callable raised; the exception is then pending.
bool wait_for_worker(OracleCall& call, std::future<void>& done, const py::object& progress) {
  std::function<void(const ProgressEvent&)> callback;
  if (!progress.is_none()) callback = python_callback(progress);
  const py::gil_scoped_release nogil;
  for (;;) {
    const bool ready = done.wait_for(std::chrono::milliseconds(50)) == std::future_status::ready;
    const py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) return false;
    try {
      for (const ProgressQueue::Event& e : call.events.take())
        if (callback) callback(ProgressEvent{e.stage, e.done, e.total});
    } catch (py::error_already_set& e) {
      e.restore();
      return false;
    }
    if (ready) return true;
  }
}

OracleSession run_on_worker(std::span<const Point3> pts, OracleSessionOptions o, const py::object& progress) {
  auto call = std::make_shared<OracleCall>();
  call->points.assign(pts.begin(), pts.end());
  call->options = std::move(o);
  call->report = !progress.is_none();
  std::future<void> done = call->done.get_future();
  std::thread worker(run_call, call);
  if (!wait_for_worker(*call, done, progress)) {
    call->cancelled = true;
    bool ended = false;
    {
      const py::gil_scoped_release nogil;
      ended = done.wait_for(std::chrono::milliseconds(500)) == std::future_status::ready;
    }
    if (ended)
      worker.join();
    else
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
  return std::move(call->session);
}

// The session on the calling thread, the GIL released; Ctrl-C through InterruptCheck,
// progress straight to the callable (which takes the GIL).
OracleSession run_here(std::span<const Point3> pts, OracleSessionOptions o, const py::object& progress) {
  std::optional<Progress> listener;
  if (!progress.is_none()) {
    const auto emit = pending_callback(progress);
    listener.emplace(emit);
    report_peers(o, emit);
  }
  OracleSession s;
  bool interrupted = false;
  {
    const InterruptCheck check;
    const py::gil_scoped_release nogil;
    const ProgressScope scope(progress_pointer(listener));
    try {
      s = run_oracle_session(pts, o);
    } catch (const ChildInterrupted&) {
      interrupted = true;  // the KeyboardInterrupt (or the callable's exception) is pending, raised below
    } catch (const std::invalid_argument& e) {
      py::gil_scoped_acquire gil;
      throw py::value_error(e.what());
    }
  }
  if (interrupted) throw py::error_already_set();
  return s;
}

py::dict session_dict(const OracleSession& s);

py::dict oracle(py::handle points, const std::vector<std::string>& against, const std::string& predicates,
                const std::string& perturb, const std::string& boundary, const std::string& order, std::uint64_t seed,
                double eps, const std::string& eps_mode, const std::string& tetgen, double timeout, double memory_mb,
                const py::dict& functions, const py::object& progress) {
  // The same kernel options as `dtlab oracle` (and tetrahedralize()).
  const KernelChoice k = kernel_choice(predicates, perturb, boundary, order, seed, eps, eps_mode);
  if (!(timeout >= 0.001 && timeout <= 1e6)) throw py::value_error("timeout: must be a number in [0.001, 1e6]");
  if (!(memory_mb >= 0 && memory_mb <= 1e9)) throw py::value_error("memory_mb: must be a number in [0, 1e9]");
  const FunctionPeers function_peers(functions);
  try {
    expand_peer_names(against);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("against: ") + e.what());
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
  if (!function_peers.names().empty()) return session_dict(run_here(pts, std::move(o), progress));
  return session_dict(run_on_worker(pts, std::move(o), progress));
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
  // The exit guard's tag for a child that Python forks (dtlab/_function_peer.py).
  m.def("guard_tag_prefix", &guard_tag_prefix, "DTLAB_GUARD's value for a child, up to its pid's digits.");
  m.def("guard_pid_digits", &guard_pid_digits, "The zero-padded width of the pid in a DTLAB_GUARD tag.");
  m.def(
      "end_tagged",
      [](int pid) {
        py::gil_scoped_release nogil;
        end_tagged(pid);
      },
      py::arg("pid"), "Kills every process whose DTLAB_GUARD carries child pid's tag (left its group).");
  // A function peer's fork under a reaper (oracle/peers/program_reaper.hpp): (reaper,
  // child) in the caller, (0, 0) in the child, with Python's own fork hooks around it.
  m.def(
      "fork_under_reaper",
      [] {
        const SpawnedChild c = fork_under_reaper({&PyOS_BeforeFork, &PyOS_AfterFork_Parent, &PyOS_AfterFork_Child});
        return std::pair<int, int>{c.reaper, c.program};
      },
      "Forks a child under a reaper that ends what it leaves: (reaper, child) in the caller, (0, 0) in the child.");
  set_interrupt_check(&host_interrupt_requested);
  m.def("oracle", &oracle, py::arg("points"), py::arg("against"), py::arg("predicates"), py::arg("perturb"),
        py::arg("boundary"), py::arg("order"), py::arg("seed"), py::arg("eps"), py::arg("eps_mode"), py::arg("tetgen"),
        py::arg("timeout"), py::arg("memory_mb"), py::arg("functions") = py::dict(), py::arg("progress") = py::none(),
        "`dtlab oracle` on an array (see dtlab.oracle).");
}

}  // namespace dtlab::python
