#pragma once
// Python callables as peers for one call (dtlab.oracle(peers=...), dtlab.fuzz.campaign(fn)):
// each name is registered with oracle/peers/peer_function.hpp for the lifetime of this object,
// its runner (dtlab._function_peer.runner(fn)) forking the child that calls fn. Made and
// destroyed with the GIL held. A Python exception in a runner (KeyboardInterrupt: the
// child is already ended) is left pending and ends the call as ChildInterrupted: the
// binding then raises it (`throw pybind11::error_already_set()`).
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

namespace dtlab::python {

class FunctionPeers {
 public:
  // runners: {name: runner}. Throws ValueError for a bad or taken name.
  explicit FunctionPeers(const pybind11::dict& runners);
  ~FunctionPeers();
  FunctionPeers(const FunctionPeers&) = delete;
  FunctionPeers& operator=(const FunctionPeers&) = delete;
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::vector<std::string> names_;
  std::vector<pybind11::object> runners_;  // alive while registered
};

}  // namespace dtlab::python
