#pragma once
// What every peer run shares with its child process: the limits it runs under and
// the verdict of a child that gave no answer (crash, hang, refusal, not installed).
#include <cstdint>
#include <optional>
#include <string>

#include "oracle/child_process.hpp"
#include "oracle/peers.hpp"

namespace dtlab {

// Half of the machine's memory (0 when it cannot be read): the default memory limit.
std::uint64_t default_peer_memory();

// The child's outcome when it gave no answer; nullopt when it exited 0. Sets run's
// times, peak memory and message (the log's last line, a signal's name). Exit status
// 4 means "not installed" for dtlab's own helpers only (`exit4_not_installed`).
std::optional<Verdict> child_failure(const ChildResult& c, const std::string& log, PeerRun& run,
                                     bool exit4_not_installed = true);

}  // namespace dtlab
