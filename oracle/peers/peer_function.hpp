#pragma once
// Peers given by a function of the host process instead of a program: the Python
// module's callables (dtlab.oracle(points, peers={"mine": fn}), dtlab.fuzz.campaign(fn)).
// The host registers a runner that calls the function in a child process it forks
// (so that the function's crash, hang or allocation is the child's end, not the
// host's) and reports how the child ended and what it answered. Once registered the
// name is a peer name like the built-in ones (oracle/peers/peers.hpp): its answer goes
// through the same adapter (any orientation, by exact sign) and the same checker.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "oracle/peers/child_process.hpp"
#include "oracle/peers/peers.hpp"

namespace dtlab {

// What a runner reports of one call.
struct FunctionAnswer {
  ChildResult child;                              // how the child ended
  bool answered = false;                          // the child sent an answer (tets or bad_answer)
  std::vector<std::array<std::int64_t, 4>> tets;  // the function's tets as it returned them (0-based)
  std::string bad_answer;  // non-empty: the return value was no (m, 4) integer array (what it was)
  double seconds = 0;      // the function's own time, measured in the child
};

// Runs the function on `points` in a child under `limits` (wall clock, RLIMIT_AS, the
// log file that takes the child's stdout and stderr). Throws ChildInterrupted when
// the host was interrupted (the child is ended first).
using PeerFunction = std::function<FunctionAnswer(std::span<const Point3> points, const ChildLimits& limits)>;

// Throws std::invalid_argument for a bad name (letters, digits, _ - . + only), a
// built-in or command peer's name, or a name already registered.
void register_function_peer(const std::string& name, PeerFunction run);
void unregister_function_peer(const std::string& name);
bool is_function_peer(const std::string& name);

// The verdicts of a command peer: a signal `crashed`, the time limit `hung`, exit
// status != 0 `refused` (the log's last line: the exception), exit 0 without an
// answer `refused`, a return value that is no (m, 4) integer array or that holds an
// index outside [0, n) `invalid`, otherwise the checker's verdict.
PeerRun run_function_peer(const std::string& name, std::span<const Point3> points, const PeerOptions& options);

}  // namespace dtlab
