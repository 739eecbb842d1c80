#pragma once
// progress= of the Python API: a dtlab::Progress (kernel/progress.hpp) that calls a
// Python callable(done, total, stage). The library calls it from the calling thread
// while the GIL is released; the call takes the GIL, also runs pending signal handlers
// (Ctrl-C), and a Python exception propagates out of the library call as
// py::error_already_set (pybind11 raises it again in Python).
#include <functional>
#include <optional>

#include <pybind11/pybind11.h>

#include "kernel/progress.hpp"
#include "oracle/peers/child_process.hpp"

namespace dtlab::python {

// The call itself. `callback` must outlive every use (the binding's argument does):
// copies of the function copy a handle, never a reference count, so they may be made
// without the GIL.
inline std::function<void(const ProgressEvent&)> python_callback(const pybind11::object& callback) {
  const pybind11::handle f = callback;
  return [f](const ProgressEvent& e) {
    pybind11::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
    f(e.done, e.total, pybind11::str(e.stage.data(), e.stage.size()));
  };
}

// python_callback for calls that stop on ChildInterrupted (oracle(), fuzz campaigns,
// whose peer runners end that way): what the callable raises is left pending, and the
// binding raises it once the call has unwound (`throw pybind11::error_already_set()`).
inline std::function<void(const ProgressEvent&)> pending_callback(const pybind11::object& callback) {
  return [call = python_callback(callback)](const ProgressEvent& e) {
    try {
      call(e);
    } catch (pybind11::error_already_set& error) {
      const pybind11::gil_scoped_acquire gil;
      error.restore();
      throw ChildInterrupted();
    }
  };
}

// Python's pending signal handlers only (progress=None): Ctrl-C reaches a long call
// without a callable too, at the same steps (about 1000 per stage).
inline std::function<void(const ProgressEvent&)> signal_callback() {
  return [](const ProgressEvent&) {
    pybind11::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
  };
}

// None: a listener that only answers Ctrl-C.
inline std::optional<Progress> python_progress(const pybind11::object& callback) {
  return Progress(callback.is_none() ? signal_callback() : python_callback(callback));
}

inline Progress* progress_pointer(std::optional<Progress>& p) { return p ? &*p : nullptr; }

}  // namespace dtlab::python
