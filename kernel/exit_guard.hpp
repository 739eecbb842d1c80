#pragma once
// What must not outlive a dtlab process, however it ends (Ctrl-C, SIGTERM, SIGHUP, even
// SIGKILL): the process groups of the programs it runs and its temporary files and
// folders. A watchdog process, forked on first use, in its own process group and deaf to
// SIGINT, SIGTERM and SIGHUP, holds the list: it learns of each entry over a socket and,
// when the socket closes (the dtlab process ended, whatever way), it kills every group
// still listed (SIGKILL) and then removes every path still listed.
#include <string>
#include <vector>

namespace dtlab {

// Listed until released. A released path that no longer exists is fine.
void guard_path(const std::string& path);
void release_path(const std::string& path);
void release_group(int pgid);

// The child side of a fork, before exec (async-signal-safe): lists the child's own
// process group. Listing it before exec leaves no window: until the exec closes the
// child's copy of the socket, the watchdog cannot see it closed. Call
// prepare_exit_guard() before the fork.
void guard_own_group_in_child();
void prepare_exit_guard();
// Set (true) just before and cleared (false) just after a fork whose child execs:
// any other fork of a guarded process gets a fresh guard of its own in the child
// (its own watchdog, the parent's death ending it: bench's measuring child).
void mark_exec_fork(bool on);

// Programs that leave their process group (setsid, setpgid) escape the group kills.
// Every program dtlab runs gets DTLAB_GUARD=<tag> in its environment, which its
// descendants inherit wherever they move: <tag> is this dtlab process's random nonce, a
// dot and the child's pid (space-separated after the tags of the dtlab processes above,
// when dtlab runs under dtlab). end_tagged(pid) kills (SIGKILL) every process whose
// environment carries the tag of child `pid`; the watchdog, when dtlab ends, every
// process that carries any tag of this dtlab process. (Jenkins' process-tree killer uses
// the same inherited marker; a program that clears its environment still escapes.)
class GuardedEnvironment {
 public:
  GuardedEnvironment();  // before the fork: this process's environment plus the tag, pid to come
  // In the child, before exec (async-signal-safe: digits written into the prepared entry).
  void stamp_child_pid();
  char* const* envp() { return pointers_.data(); }
  // In the parent, after the fork: end_tagged(child_pid) reads only the environments of
  // processes newer than this object (the pids running at its construction are kept).
  void started(int child_pid);

 private:
  std::vector<int> before_;
  std::vector<std::string> entries_;
  std::vector<char*> pointers_;
  std::size_t guard_ = 0, digits_ = 0;  // the DTLAB_GUARD entry and where its pid digits go
};
void end_tagged(int child_pid);
// For a child forked by other code (Python's function peers fork in Python): its
// DTLAB_GUARD value is guard_tag_prefix() followed by its pid in guard_pid_digits()
// zero-padded digits, set in the child before it runs anything; end_tagged(pid) then
// finds its descendants as for the children above. Starts the guard (the nonce).
std::string guard_tag_prefix();
int guard_pid_digits();

// The interrupt path: ends every listed group, removes every listed path and waits
// for the watchdog to finish; later guard and release calls block for ever (the
// process is about to end).
void end_guarded_now();

// SIGINT, SIGTERM and SIGHUP end the process as the shell expects (died of the signal:
// status 130, 143, 129) after end_guarded_now(); they are unblocked first (a blocked mask
// is inherited across exec), and one ignored when the program starts stays ignored. For
// programs (the dtlab command), not for a library loaded into someone else's process
// (the Python module).
void install_interrupt_cleanup();

// True once install_interrupt_cleanup's handler received a signal: code that notices a
// child it waits for died must not report that death as the child's answer.
bool interrupt_received();

// Blocks the calling thread until the interrupt handler ends the process.
[[noreturn]] void wait_for_interrupt_exit();

}  // namespace dtlab
