#pragma once
// Python's Ctrl-C while a call runs peers. The child runner (oracle/peers/child_process.hpp)
// polls one host check, set once by the module (bind_oracle): host_interrupt_requested.
// It answers per thread:
// - a worker thread of oracle() (t_cancelled set): whether its caller saw Ctrl-C, as the
//   caller checks Python's signals itself every 50 ms;
// - a calling thread inside an InterruptCheck (function peers, fuzz campaigns): Python's
//   own pending signals, taken with the GIL;
// - any other thread: never.
// So a KeyboardInterrupt answers within a poll interval instead of after a peer's timeout.
#include <pybind11/pybind11.h>

#include <atomic>

#include "oracle/peers/child_process.hpp"

namespace dtlab::python {

inline thread_local const std::atomic<bool>* t_cancelled = nullptr;
inline thread_local bool t_poll_python = false;

inline bool host_interrupt_requested() {
  if (t_cancelled) return t_cancelled->load();
  if (!t_poll_python) return false;
  pybind11::gil_scoped_acquire gil;
  return PyErr_CheckSignals() != 0;
}

// Scope of a call that runs peers on the calling thread (GIL released meanwhile).
struct InterruptCheck {
  InterruptCheck() : previous_(t_poll_python) { t_poll_python = true; }
  ~InterruptCheck() { t_poll_python = previous_; }
  InterruptCheck(const InterruptCheck&) = delete;
  InterruptCheck& operator=(const InterruptCheck&) = delete;

 private:
  bool previous_;
};

}  // namespace dtlab::python
