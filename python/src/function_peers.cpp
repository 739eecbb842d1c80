#include "python/src/function_peers.hpp"

#include <cstring>
#include <stdexcept>

#include "oracle/peers/peer_function.hpp"
#include "python/src/numpy_io.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

ChildStatus status_of(const std::string& s) {
  if (s == "exited") return ChildStatus::exited;
  if (s == "signaled") return ChildStatus::signaled;
  if (s == "timed_out") return ChildStatus::timed_out;
  return ChildStatus::not_started;
}

// The child's bytes (dtlab/_function_peer.py): b"T", f64 seconds, u64 m, m x 4 int64;
// or b"B" and why the return value is no tets array.
void read_answer(const std::string& bytes, FunctionAnswer& a) {
  if (bytes.empty()) return;
  a.answered = true;
  if (bytes[0] == 'B') {
    a.bad_answer = bytes.substr(1);
    return;
  }
  std::uint64_t m = 0;
  if (bytes[0] != 'T' || bytes.size() < 17) {
    a.bad_answer = "unreadable answer from the child";
    return;
  }
  std::memcpy(&a.seconds, bytes.data() + 1, 8);
  std::memcpy(&m, bytes.data() + 9, 8);
  if (m > (bytes.size() - 17) / 32 || bytes.size() - 17 != m * 32) {
    a.bad_answer = "truncated answer from the child";
    return;
  }
  a.tets.resize(m);
  if (m) std::memcpy(a.tets.data(), bytes.data() + 17, m * 32);
}

FunctionAnswer call_runner(PyObject* runner, std::span<const Point3> points, const ChildLimits& limits) {
  py::gil_scoped_acquire gil;
  FunctionAnswer a;
  try {
    py::tuple r =
        py::reinterpret_borrow<py::object>(runner)(points_to_numpy(std::vector<Point3>(points.begin(), points.end())),
                                                   limits.timeout_s, limits.memory_bytes, limits.log_path);
    a.child.status = status_of(r[0].cast<std::string>());
    a.child.exit_code = r[1].cast<int>();
    a.child.signal = r[2].cast<int>();
    a.child.seconds = r[3].cast<double>();
    a.child.peak_rss_bytes = r[4].cast<std::uint64_t>();
    if (a.child.status == ChildStatus::not_started)
      a.child.message = r[5].cast<std::string>();
    else
      read_answer(r[5].cast<std::string>(), a);
  } catch (py::error_already_set& e) {
    e.restore();  // raised by the binding once the call has unwound
    throw ChildInterrupted();
  }
  return a;
}

}  // namespace

FunctionPeers::FunctionPeers(const py::dict& runners) {
  try {
    for (const auto& [key, value] : runners) {
      const std::string name = py::cast<std::string>(key);
      PyObject* raw = value.ptr();
      register_function_peer(name, [raw](std::span<const Point3> points, const ChildLimits& limits) {
        return call_runner(raw, points, limits);
      });
      names_.push_back(name);
      runners_.push_back(py::reinterpret_borrow<py::object>(value));
    }
  } catch (const std::invalid_argument& e) {
    for (const auto& n : names_) unregister_function_peer(n);
    throw py::value_error(std::string("peers: ") + e.what());
  }
}

FunctionPeers::~FunctionPeers() {
  for (const auto& n : names_) unregister_function_peer(n);
}

}  // namespace dtlab::python
