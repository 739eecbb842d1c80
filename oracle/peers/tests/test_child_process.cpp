// The child-process runner: exit codes, crashes, time-outs (the whole process
// group killed), programs that do not exist, memory limits, bad time-outs.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "oracle/peers/child_process.hpp"
#include "oracle/peers/temp_dir.hpp"

using namespace dtlab;

namespace {

// A process is gone when /proc has no entry for it, or it is a zombie nobody reaped.
bool process_gone(int pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  if (!stat) return true;
  std::string line;
  std::getline(stat, line);
  const auto close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'Z';
}

}  // namespace

TEST_CASE("run_child reports exit codes, signals and output", "[oracle][child]") {
  TempDir dir;
  const std::string log = dir.file("log");
  ChildResult r = run_child({"sh", "-c", "echo first; echo 'the message'; exit 7"}, ChildLimits::of(30, log));
  CHECK(r.status == ChildStatus::exited);
  CHECK(r.exit_code == 7);
  CHECK(last_line_of(log) == "the message");

  r = run_child({"sh", "-c", "kill -SEGV $$"}, ChildLimits::of(30));
  CHECK(r.status == ChildStatus::signaled);
  CHECK(r.signal == SIGSEGV);

  r = run_child({"/nonexistent/dtlab-no-such-program"}, ChildLimits::of(30));
  CHECK(r.status == ChildStatus::not_started);
  CHECK(r.message.find("No such file") != std::string::npos);
}

TEST_CASE("run_child kills the whole process group on time-out", "[oracle][child]") {
  TempDir dir;
  const std::string pidfile = dir.file("pid");
  // The grandchild outlives an ordinary kill of its parent; the group kill gets it.
  const ChildResult r = run_child({"sh", "-c", "sleep 30 & echo $! > " + pidfile + "; wait"}, ChildLimits::of(0.5));
  CHECK(r.status == ChildStatus::timed_out);
  CHECK(r.seconds < 10);
  int grandchild = 0;
  std::ifstream(pidfile) >> grandchild;
  REQUIRE(grandchild > 0);
  bool gone = false;
  for (int i = 0; i < 100 && !gone; ++i) {
    gone = process_gone(grandchild);
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  CHECK(gone);
}

// Waits up to 2 s for `pid` to be gone.
bool ends_soon(int pid) {
  for (int i = 0; i < 100; ++i) {
    if (process_gone(pid)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

TEST_CASE("a program's descendant in a session of its own with an empty environment is ended", "[oracle][child]") {
  // Neither the group kill nor the DTLAB_GUARD tag finds it: the program's reaper does.
  TempDir dir;
  const std::string pidfile = dir.file("pid");
  const std::string script = "env -i setsid sleep 30 & echo $! > " + pidfile + "; sleep 0.2";
  for (const double timeout : {30.0, 0.1}) {  // the program exits, or is killed at its time limit
    INFO("timeout " << timeout);
    std::remove(pidfile.c_str());
    const ChildResult r = run_child({"sh", "-c", script + (timeout < 1 ? "; sleep 30" : "")}, ChildLimits::of(timeout));
    CHECK(r.status == (timeout < 1 ? ChildStatus::timed_out : ChildStatus::exited));
    int escaped = 0;
    std::ifstream(pidfile) >> escaped;
    REQUIRE(escaped > 0);
    CHECK(ends_soon(escaped));
  }
}

TEST_CASE("fork_under_reaper: the fork's escaped descendant is ended, its exit read through the reaper",
          "[oracle][child]") {
  TempDir dir;
  const std::string pidfile = dir.file("pid");
  const SpawnedChild c = fork_under_reaper();
  if (c.reaper == 0) {  // the fork: an escapee, then exit 5
    const int code = std::system(("env -i setsid sleep 30 & echo $! > " + pidfile).c_str());
    _exit(code == 0 ? 5 : 1);
  }
  REQUIRE(c.reaper > 0);
  REQUIRE(c.program > 0);
  CHECK(c.program != c.reaper);
  int status = 0;
  REQUIRE(waitpid(c.reaper, &status, 0) == c.reaper);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 5);
  int escaped = 0;
  std::ifstream(pidfile) >> escaped;
  REQUIRE(escaped > 0);
  CHECK(ends_soon(escaped));
}

TEST_CASE("run_child measures the program's own peak memory, not the parent's", "[oracle][child]") {
  // The parent holds 300 MB; the child program (sleep) a few: fork would have counted both.
  std::vector<char> ballast(300u << 20, 1);
  const ChildResult r = run_child({"sleep", "0.3"}, ChildLimits::of(30));
  CHECK(ballast[12345] == 1);
  CHECK(r.status == ChildStatus::exited);
  CHECK(r.peak_rss_bytes > 0);
  CHECK(r.peak_rss_bytes < (50u << 20));
}

TEST_CASE("run_child applies the memory limit", "[oracle][child]") {
  // 2 GB under a 256 MB address-space limit: the allocation fails in the child.
  const ChildResult r = run_child({"python3", "-c", "x = bytearray(2 * 10**9)"}, ChildLimits::of(60, "", 256ull << 20));
  if (r.status == ChildStatus::not_started) {
    WARN("python3 not installed");
    return;
  }
  CHECK(r.status == ChildStatus::exited);
  CHECK(r.exit_code != 0);
  CHECK(r.peak_rss_bytes < (256ull << 20));
}

TEST_CASE("run_child rejects a NaN, infinite, zero or negative timeout", "[oracle][child]") {
  for (double t : {std::nan(""), std::numeric_limits<double>::infinity(), 0.0, -1.0})
    CHECK_THROWS_AS(run_child({"true"}, ChildLimits::of(t)), std::invalid_argument);
  CHECK_THROWS_AS(run_child({}, ChildLimits::of(1)), std::invalid_argument);
}
