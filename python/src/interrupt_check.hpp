#pragma once
// Python's Ctrl-C while a call runs peers: the child runner (oracle/child_process.hpp)
// polls this check, so a KeyboardInterrupt answers within its poll interval instead
// of after the peer's timeout. One per call that runs peers, on the calling thread.
#include <pybind11/pybind11.h>

#include "oracle/child_process.hpp"

namespace dtlab::python {

inline bool python_signal_pending() {
  pybind11::gil_scoped_acquire gil;
  return PyErr_CheckSignals() != 0;
}

struct InterruptCheck {
  InterruptCheck() { set_interrupt_check(&python_signal_pending); }
  ~InterruptCheck() { set_interrupt_check(nullptr); }
  InterruptCheck(const InterruptCheck&) = delete;
  InterruptCheck& operator=(const InterruptCheck&) = delete;
};

}  // namespace dtlab::python
