#pragma once
// A long-lived child process that answers requests: one line on its stdin each, one
// reply line "CODE MESSAGE" on its fd 3 (its stdout and stderr go to a log file). The
// limits of run_child hold (own process group, RLIMIT_AS, a wall-clock limit per
// request); a crash or a hang ends it, and the next request starts it again.
// The peer helpers' --serve mode (PeerServers, oracle/peers/peers.hpp) runs on it, so that a
// helper whose start costs most of a small run (gmsh's libraries, scipy's import)
// pays it once per shrink instead of once per try.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "oracle/peers/child_process.hpp"
#include "oracle/peers/temp_dir.hpp"

namespace dtlab {

class ServedChild {
 public:
  // `limits.timeout_s` is ignored (each request has its own); log_path must be set.
  ServedChild(std::vector<std::string> argv, ChildLimits limits);
  ~ServedChild();
  ServedChild(const ServedChild&) = delete;
  ServedChild& operator=(const ServedChild&) = delete;

  // Sends `request` (one line, no newline) and waits up to timeout_s for the reply.
  // Answered: status exited, exit_code the reply's leading number, `reply` the rest of
  // its line, peak_rss_bytes the peak during this request. A child that died or hung
  // is reported as run_child would (signaled, exited with its status, timed_out) and
  // is started afresh on the next request; not_started when it cannot start.
  ChildResult ask(const std::string& request, double timeout_s, std::string& reply);

  int pid() const { return child_.program; }  // the program's; -1 when not running

 private:
  bool start(ChildResult& r);
  // Ends the child (EOF on its stdin, then SIGKILL to its group) and reaps it;
  // `status` gets its wait status when set; true when it had to be killed.
  bool stop(int* status = nullptr);

  std::vector<std::string> argv_;
  ChildLimits limits_;
  SpawnedChild child_;
  int to_ = -1;    // our end of its stdin (a socket: writes never raise SIGPIPE)
  int from_ = -1;  // our end of its fd 3
  std::string buffer_;
};

// Served children by key, each started on its first request and ended with the pool
// (their logs in a temporary folder of the pool's). Not thread-safe: one per thread.
class ServedChildren {
 public:
  ServedChild& get(const std::string& key, const std::vector<std::string>& argv, ChildLimits limits);

 private:
  TempDir logs_{"dtlab-served"};
  std::map<std::string, std::unique_ptr<ServedChild>> children_;
};

}  // namespace dtlab
