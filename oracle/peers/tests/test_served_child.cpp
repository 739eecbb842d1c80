// ServedChild: one process answers request after request; a crash or a hang ends
// only that request (the next one starts it afresh); a missing program is not_started.
#include <catch2/catch.hpp>

#include <signal.h>

#include <string>

#include "oracle/peers/served_child.hpp"
#include "oracle/peers/temp_dir.hpp"

using namespace dtlab;

namespace {

// A shell server: "crash" kills it, "hang" sleeps, "refuse" replies 3, else echoes.
const char* kServer = R"SH(
while read -r line; do
  case "$line" in
    crash) kill -SEGV $$ ;;
    hang) sleep 30 ;;
    refuse) echo "3 no thanks" >&3 ;;
    *) echo "noise on stdout"; echo "0 got $line" >&3 ;;
  esac
done
)SH";

ChildLimits limits(const TempDir& dir) { return ChildLimits::of(1, dir.file("log")); }

}  // namespace

TEST_CASE("a served child answers many requests in one process", "[oracle][child]") {
  TempDir dir;
  ServedChild child({"sh", "-c", kServer}, limits(dir));
  std::string reply;
  ChildResult r = child.ask("a", 30, reply);
  REQUIRE(r.status == ChildStatus::exited);
  CHECK(r.exit_code == 0);
  CHECK(reply == "got a");
  const int pid = child.pid();
  r = child.ask("b c", 30, reply);
  CHECK(reply == "got b c");
  CHECK(child.pid() == pid);
  r = child.ask("refuse", 30, reply);
  CHECK(r.exit_code == 3);
  CHECK(reply == "no thanks");
  CHECK(child.pid() == pid);
}

TEST_CASE("a served child that crashes or hangs is started again", "[oracle][child]") {
  TempDir dir;
  ServedChild child({"sh", "-c", kServer}, limits(dir));
  std::string reply;
  ChildResult r = child.ask("crash", 30, reply);
  CHECK(r.status == ChildStatus::signaled);
  CHECK(r.signal == SIGSEGV);
  CHECK(child.pid() < 0);
  r = child.ask("again", 30, reply);
  CHECK(r.status == ChildStatus::exited);
  CHECK(reply == "got again");

  r = child.ask("hang", 0.3, reply);
  CHECK(r.status == ChildStatus::timed_out);
  CHECK(r.seconds < 10);
  r = child.ask("after", 30, reply);
  CHECK(r.status == ChildStatus::exited);
  CHECK(reply == "got after");

  ServedChild missing({"/nonexistent/dtlab-no-such-server"}, limits(dir));
  r = missing.ask("x", 30, reply);
  CHECK(r.status == ChildStatus::not_started);

  ServedChildren pool;
  ServedChild& a = pool.get("k", {"sh", "-c", kServer}, limits(dir));
  CHECK(&pool.get("k", {"sh", "-c", kServer}, limits(dir)) == &a);
  CHECK(a.ask("p", 30, reply).exit_code == 0);
}
