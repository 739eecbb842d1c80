// Function peers (oracle/peers/peer_function.hpp) without Python: a runner that reports a
// made-up child end and answer, so that each maps to its verdict through run_peer.
#include <catch2/catch.hpp>

#include <signal.h>

#include <stdexcept>

#include "oracle/peers/peer_function.hpp"
#include "oracle/peers/peers.hpp"

using namespace dtlab;

namespace {

const std::vector<Point3> kCube = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};

// The cube corner's two tets, written in both orientations (the adapter orients them).
FunctionAnswer good_answer() {
  FunctionAnswer a;
  a.child.status = ChildStatus::exited;
  a.child.exit_code = 0;
  a.answered = true;
  a.tets = {{0, 1, 2, 3}, {2, 1, 3, 4}};
  return a;
}

PeerRun run_with(FunctionAnswer answer) {
  register_function_peer("fake", [answer](std::span<const Point3>, const ChildLimits&) { return answer; });
  PeerRun r = run_peer("fake", kCube);
  unregister_function_peer("fake");
  return r;
}

}  // namespace

TEST_CASE("a function peer's answer goes through the adapter and the checker", "[oracle][peers]") {
  const PeerRun r = run_with(good_answer());
  CHECK(r.verdict == Verdict::delaunay);
  REQUIRE(r.mesh);
  CHECK(r.mesh->tets.size() == 2);
  CHECK_FALSE(is_function_peer("fake"));
  CHECK_FALSE(is_peer_name("fake"));
}

TEST_CASE("a function peer's child end and bad answers are verdicts", "[oracle][peers]") {
  FunctionAnswer a = good_answer();
  a.child.status = ChildStatus::signaled;
  a.child.signal = SIGSEGV;
  CHECK(run_with(a).verdict == Verdict::crashed);
  a = good_answer();
  a.child.status = ChildStatus::timed_out;
  CHECK(run_with(a).verdict == Verdict::hung);
  a = good_answer();
  a.child.exit_code = 1;
  CHECK(run_with(a).verdict == Verdict::refused);
  a = good_answer();
  a.answered = false;
  const PeerRun silent = run_with(a);
  CHECK(silent.verdict == Verdict::refused);
  CHECK(silent.message == "exited 0 without an answer");
  a = good_answer();
  a.tets[1][3] = 5;  // one past the last point
  const PeerRun beyond = run_with(a);
  CHECK(beyond.verdict == Verdict::invalid);
  CHECK(beyond.message == "wrong answer: tet 1 has vertex 5, not an index of the 5 points (0-based)");
  a.tets[1][3] = -1;
  CHECK(run_with(a).verdict == Verdict::invalid);
  a = good_answer();
  a.bad_answer = "shape (2, 3), expected (m, 4)";
  CHECK(run_with(a).message == "wrong answer: shape (2, 3), expected (m, 4)");
  a = good_answer();
  a.tets.pop_back();  // point 4 in no tet
  const PeerRun half = run_with(a);
  CHECK(half.verdict == Verdict::missing_points);  // the checker's verdict
  REQUIRE(half.report);
  CHECK_FALSE(half.report->ok());
}

TEST_CASE("function peer names are checked", "[oracle][peers]") {
  const auto none = [](std::span<const Point3>, const ChildLimits&) { return FunctionAnswer{}; };
  CHECK_THROWS_AS(register_function_peer("cgal", none), std::invalid_argument);
  CHECK_THROWS_AS(register_function_peer("two words", none), std::invalid_argument);
  CHECK_THROWS_AS(register_function_peer("all", none), std::invalid_argument);
  register_function_peer("once", none);
  CHECK_THROWS_AS(register_function_peer("once", none), std::invalid_argument);
  unregister_function_peer("once");
}
