// The runner's grading of a child that ran out of memory or wrote without bound, its
// forked-function mode (bench's measuring child), and the verdicts these become for a
// peer: a peer that allocates without bound is out-of-memory, not refused.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>

#include <stdexcept>
#include <string>
#include <vector>

#include "oracle/check/tests/point_sets.hpp"
#include "oracle/peers/child_process.hpp"
#include "oracle/peers/peer_command.hpp"
#include "oracle/peers/peers.hpp"
#include "oracle/peers/temp_dir.hpp"

using namespace dtlab;

namespace {

// Python appending 10 MB blocks until an allocation fails (MemoryError under RLIMIT_AS).
const char* kHog = "x = []\nwhile True: x.append(bytearray(10**7))";

bool have_python() { return access("/usr/bin/python3", X_OK) == 0; }

}  // namespace

TEST_CASE("run_child grades a failed allocation and a foreign SIGKILL as out of memory", "[oracle][child]") {
  if (!have_python()) {
    WARN("python3 not installed");
    return;
  }
  TempDir dir;
  const std::string log = dir.file("log");
  ChildResult r = run_child({"/usr/bin/python3", "-c", kHog}, ChildLimits::of(60, log, 256ull << 20));
  CHECK(r.status == ChildStatus::exited);
  CHECK(r.exit_code != 0);
  CHECK(r.out_of_memory);
  CHECK(last_line_of(log) == "MemoryError");

  r = run_child({"sh", "-c", "kill -KILL $$"}, ChildLimits::of(30, log));
  CHECK(r.status == ChildStatus::signaled);
  CHECK(r.out_of_memory);

  // An ordinary failure and an ordinary crash are not memory.
  r = run_child({"sh", "-c", "echo 'no such thing'; exit 3"}, ChildLimits::of(30, log));
  CHECK(r.exit_code == 3);
  CHECK_FALSE(r.out_of_memory);
  r = run_child({"sh", "-c", "kill -SEGV $$"}, ChildLimits::of(30, log));
  CHECK(r.status == ChildStatus::signaled);
  CHECK_FALSE(r.out_of_memory);
  // Our own kill at the time limit is a hang, not memory.
  r = run_child({"sleep", "30"}, ChildLimits::of(0.3, log));
  CHECK(r.status == ChildStatus::timed_out);
  CHECK_FALSE(r.out_of_memory);
}

TEST_CASE("run_child kills a child whose output passes the cap", "[oracle][child]") {
  TempDir dir;
  ChildLimits limits = ChildLimits::of(60, dir.file("log"));
  limits.log_cap_bytes = 1u << 20;
  const ChildResult r = run_child({"yes"}, limits);
  CHECK(r.status == ChildStatus::output_limit);
  CHECK(r.seconds < 30);
  CHECK(r.message.find("1 MiB") != std::string::npos);
}

TEST_CASE("run_forked runs a function in a child and returns what it wrote", "[oracle][child]") {
  std::string reply;
  ChildResult r = run_forked([](int fd) { (void)!write(fd, "hello", 5); }, ChildLimits::of(30), reply);
  CHECK(r.status == ChildStatus::exited);
  CHECK(r.exit_code == 0);
  CHECK(reply == "hello");
  CHECK(r.maxrss_bytes > 0);

  TempDir dir;
  r = run_forked([](int) { throw std::runtime_error("the message"); }, ChildLimits::of(30, dir.file("log")), reply);
  CHECK(r.exit_code == 70);
  CHECK(reply.empty());
  CHECK(last_line_of(dir.file("log")) == "the message");

  r = run_forked([](int) { sleep(30); }, ChildLimits::of(0.3), reply);
  CHECK(r.status == ChildStatus::timed_out);
}

TEST_CASE("a peer that allocates without bound is graded out-of-memory, not refused", "[oracle][peers]") {
  if (!have_python()) {
    WARN("python3 not installed");
    return;
  }
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
  // (Command peers run without RLIMIT_AS in sanitizer builds: nothing would stop the hog.)
  const CommandPeer hog = make_command_peer("hog", {"/usr/bin/python3", "-c", kHog, "{in}", "{out}"});
  PeerOptions o;
  o.timeout_s = 60;
  o.memory_bytes = 256ull << 20;
  const PeerRun r = run_command_peer(hog, test::uniform_points(20, 1), o);
  INFO(r.message);
  CHECK(r.verdict == Verdict::out_of_memory);
  CHECK(std::string(verdict_name(r.verdict)) == "out-of-memory");
  CHECK(no_answer(r.verdict));
  CHECK(r.message == "MemoryError");
#endif

  // A helper peer whose allocation failed (dtlab_peer's "out of memory: std::bad_alloc").
  TempDir dir;
  const std::string helper = dir.file("peer.sh");
  {
    std::FILE* f = std::fopen(helper.c_str(), "w");
    REQUIRE(f);
    std::fputs("#!/bin/sh\necho 'out of memory: std::bad_alloc' >&2\nexit 3\n", f);
    std::fclose(f);
  }
  chmod(helper.c_str(), 0755);
  PeerOptions h;
  h.timeout_s = 30;
  h.peer_binary = helper;
  const PeerRun b = run_peer("cgal", test::uniform_points(20, 1), h);
  CHECK(b.verdict == Verdict::out_of_memory);
  CHECK(b.message == "out of memory: std::bad_alloc");
}
