#pragma once
// What every peer run shares with its child process: the limits it runs under and
// the verdict of a child that gave no answer (crash, hang, refusal, not installed).
#include <cstdint>
#include <optional>
#include <string>

#include "oracle/peers/child_process.hpp"
#include "oracle/peers/peers.hpp"

namespace dtlab {

// Half of the machine's memory (0 when it cannot be read): the default memory limit.
std::uint64_t default_peer_memory();

// The limits of one peer child: options' time limit and memory (default_peer_memory()
// when 0), stdout and stderr into `log`. An AddressSanitizer or ThreadSanitizer build
// of our own programs reserves terabytes of shadow address space as it starts, so
// RLIMIT_AS would kill it before it runs: in sanitizer builds only, a child that
// `may_be_instrumented` (our helpers, a command or a forked host) runs without the
// memory limit (the time limit stays).
ChildLimits peer_limits(const PeerOptions& options, const std::string& log, bool may_be_instrumented);

// The child's outcome when it gave no answer; nullopt when it exited 0. Sets run's
// times, peak memory and message (the log's last line, a signal's name). Exit status
// 4 means "not installed" for dtlab's own helpers only (`exit4_not_installed`).
std::optional<Verdict> child_failure(const ChildResult& c, const std::string& log, PeerRun& run,
                                     bool exit4_not_installed = true);

}  // namespace dtlab
