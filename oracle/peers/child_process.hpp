#pragma once
// The one runner of dtlab's child processes (peers, TetGen, bench's measuring
// children): a program (run_child) or a function of ours in a fork (run_forked) under a
// wall-clock limit and a memory limit, in its own process group, listed with the exit
// watchdog (kernel/exit_guard.hpp), its stdout and stderr captured under a size cap, and
// its end classified (ChildStatus, out_of_memory), so that neither a crash, nor a hang,
// nor a runaway allocation or output of the child can take the caller down. On time-out
// the whole process group is killed (a shell or python wrapper takes its children along),
// and a program's reaper ends the descendants that left the group.
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dtlab {

struct ChildLimits {
  double timeout_s = 600;          // wall clock; must be finite and > 0
  std::uint64_t memory_bytes = 0;  // RLIMIT_AS of the child; 0: no limit
  std::string log_path;            // stdout and stderr of the child; "": /dev/null
  // The log (or run_forked's reply) may grow to this size; a child writing more is
  // killed (output_limit). Checked at each poll (every 1-20 ms), so a fast writer may
  // pass it by what it writes in one poll interval. 0: no cap.
  std::uint64_t log_cap_bytes = std::uint64_t{64} << 20;

  static ChildLimits of(double timeout_s, std::string log_path = "", std::uint64_t memory_bytes = 0) {
    ChildLimits l;
    l.timeout_s = timeout_s;
    l.log_path = std::move(log_path);
    l.memory_bytes = memory_bytes;
    return l;
  }
};

enum class ChildStatus {
  exited,        // exit_code is set
  signaled,      // signal is set (a crash: SIGSEGV, SIGABRT, ...)
  timed_out,     // killed (with its process group) after timeout_s
  not_started,   // the program does not exist or cannot be executed (message)
  output_limit,  // killed (with its process group): its output passed log_cap_bytes
};

struct ChildResult {
  ChildStatus status = ChildStatus::not_started;
  int exit_code = -1;
  int signal = 0;
  double seconds = 0;                // wall time of the child
  std::uint64_t peak_rss_bytes = 0;  // the program's peak resident memory (VmHWM after exec),
                                     // sampled every 1-20 ms while it runs; 0: ended before a sample
  std::uint64_t maxrss_bytes = 0;    // ru_maxrss of the waited child (a fork child: its whole peak)
  std::string message;               // why it did not start, or why out_of_memory
  // Ended for lack of memory: killed by SIGKILL that was not our time-out (the kernel's
  // OOM killer, a cgroup limit), or it failed with an allocation failure on the last
  // lines of its log (std::bad_alloc, MemoryError, "out of memory", "cannot allocate",
  // "memory exhausted": what RLIMIT_AS makes of a runaway allocation).
  bool out_of_memory = false;
};

// argv[0] is looked up in PATH when it has no '/'. Throws std::invalid_argument for
// an empty argv or a NaN, infinite, zero or negative timeout.
ChildResult run_child(const std::vector<std::string>& argv, const ChildLimits& limits);

// Whether run_child could start `program`: with a '/', an executable regular file there;
// else one in some directory of $PATH (an empty entry is the current directory). For
// commands that would otherwise find a missing program only after their work.
bool program_found(const std::string& program);

// `body` run in a forked child of this process (no exec) under the same limits, own
// process group and classification as run_child; the child ends the parent's death
// (the exit watchdog's plain-fork rule) and its stdout and stderr go to limits.log_path.
// What body writes to the descriptor it is given comes back in `reply` (at most
// log_cap_bytes); the child exits 0 when body returns, 70 when it throws.
ChildResult run_forked(const std::function<void(int reply_fd)>& body, const ChildLimits& limits, std::string& reply);

// Fills r's status, signal, exit code and out_of_memory from a wait status, the log's
// last lines deciding out_of_memory (run_child, run_forked and ServedChild share it).
void classify_child_end(int wait_status, const std::string& log_path, ChildResult& r);
// True when `text` (a log's end, a helper's reply) tells of a failed allocation.
bool mentions_allocation_failure(std::string text);

// A program started by spawn_child: `program` leads its own process group (the group
// kills, the DTLAB_GUARD tag, the peak memory); `reaper` is its parent, the child of this
// process to wait for, which ends everything the program leaves behind and then exits
// as the program did (oracle/peers/program_reaper.hpp). For a forked body (run_forked)
// both are the fork. -1: not started.
struct SpawnedChild {
  int reaper = -1;
  int program = -1;
};

// The lower level of run_child (and of ServedChild, oracle/peers/served_child.hpp): starts
// argv under its reaper, in its own process group, under limits' memory limit, stdout and
// stderr to limits.log_path, stdin from `stdin_fd` (-1: /dev/null) and, when
// reply_fd >= 0, that descriptor as the program's fd 3. Returns both pids, or -1s with
// `message` set when it did not start. The caller waits for the reaper.
SpawnedChild spawn_child(const std::vector<std::string>& argv, const ChildLimits& limits, int stdin_fd, int reply_fd,
                         std::string& message);

// A fork of this process that goes on running the caller's code (Python's function
// peers, dtlab/_function_peer.py) under a reaper like spawn_child's program: returns
// {reaper, program} in the caller and {0, 0} in the program, which leads its own group
// and is a plain fork for the exit guard (its own watchdog, its parent's death ends it).
// `before`, `after_parent` and `after_child` are a host's fork hooks (Python's
// PyOS_BeforeFork, PyOS_AfterFork_Parent, PyOS_AfterFork_Child; the child's runs in the
// program). The caller waits for the reaper. Throws std::system_error when a fork fails.
struct ForkHooks {
  void (*before)() = nullptr;
  void (*after_parent)() = nullptr;
  void (*after_child)() = nullptr;
};
SpawnedChild fork_under_reaper(const ForkHooks& hooks = {});

// Interrupts. Every child's process group is listed with the exit watchdog
// (kernel/exit_guard.hpp) from before its exec until it is reaped, so no child outlives
// dtlab, even a dtlab killed with SIGKILL. A host that handles Ctrl-C itself (the
// Python module) sets a check, polled while a child runs (at least every 0.1 s): when
// it returns true the child's group is killed and run_child and ServedChild::ask throw
// ChildInterrupted. nullptr: no check.
struct ChildInterrupted : std::runtime_error {
  ChildInterrupted() : std::runtime_error("interrupted") {}
};
void set_interrupt_check(bool (*check)());
// The check's answer now (false without one).
bool interrupt_requested();

// The peak resident memory of the program process `pid` now runs (VmHWM, from /proc),
// 0 when it cannot be read. rusage's ru_maxrss cannot serve: it includes the parent's
// pages the child held between fork and exec.
std::uint64_t vm_hwm_bytes(int pid);

// The last non-empty line of a text file (at most the last 4 KiB are read); "" when
// the file is missing or empty. A refusing program's message.
std::string last_line_of(const std::string& path);

}  // namespace dtlab
