// The leaderboard's shrink stage with stand-in peers (shell scripts in place of the
// helper, deciding by the number of input points): later passes finish the pairs the
// first stopped, and a hang shrinks under a short limit per try, confirmed (or not)
// under the full one, within the stage's budget.
#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "experiments/peer_campaign.hpp"
#include "experiments/shrink_stage.hpp"
#include "oracle/peers/peers.hpp"
#include "oracle/peers/temp_dir.hpp"

using namespace dtlab;
using namespace dtlab::experiments;

namespace {

// A helper script: `body` sees the number of input points as $n ($2 is the input file).
std::string stand_in(const TempDir& dir, const std::string& name, const std::string& body) {
  const std::string path = dir.file(name);
  std::ofstream(path) << "#!/bin/sh\nn=$(( ($(stat -c %s \"$2\") - 12) / 24 ))\n" << body << "\n";
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
  return path;
}

std::vector<Point3> uniform(std::size_t n, std::uint64_t seed) {
  return fuzz_family_sources({"uniform"})[0].generate(n, seed);
}

PeerCase failing_case(std::size_t index, std::size_t n, Verdict v, double wall_seconds) {
  PeerCase c;
  c.peer = "cgal";
  c.source = "uniform";
  c.index = index;
  c.n = n;
  c.run.verdict = v;
  c.run.wall_seconds = wall_seconds;
  return c;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

TEST_CASE("shrink stage: later passes go on with the pairs the first stopped by time", "[experiments][shrink]") {
  TempDir dir;
  // Refuses 12 points or more (slowly), crashes on fewer: a refusal on 16 points
  // shrinks to 12, and proving those 1-minimal takes 12 runs more: 2.4 s at least.
  ShrinkStageOptions o;
  o.peer_options.peer_binary = stand_in(dir, "peer.sh", "sleep 0.1\n[ $n -ge 12 ] && exit 3\nkill -SEGV $$");
  o.peer_options.timeout_s = 30;
  o.jobs = 1;
  o.seconds = 12;
  o.out_dir = dir.path().string();
  // Pair 0 first, then eleven that are done at once (4 points: every subset is flat):
  // pass one gives pair 0 a share of 12 s / 12 pairs, too little; pass two the rest.
  std::vector<PeerCase> cases;
  cases.push_back(failing_case(0, 16, Verdict::refused, 0.1));
  for (std::size_t i = 1; i < 12; ++i) cases.push_back(failing_case(i, 4, Verdict::crashed, 0.1));
  std::vector<ShrinkPair> pairs;
  for (auto& c : cases) pairs.push_back({&c, uniform(c.n, c.index + 1), "test", 0});
  const auto t0 = std::chrono::steady_clock::now();
  const ShrinkStageResult r = run_shrink_stage(pairs, o);
  CHECK(seconds_since(t0) < o.seconds + 2);
  REQUIRE(r.pass_seconds.size() >= 2);
  CHECK(r.pass_pairs[0] == 12);
  CHECK(r.pass_pairs[1] == 1);
  const PeerCase& c = cases[0];
  CHECK(c.shrunk_minimal);
  CHECK(c.shrink_stop.empty());
  CHECK(c.shrunk_points == 12);
  CHECK(c.shrink_passes == r.pass_seconds.size());
  CHECK(c.shrink_runs >= 12);
  CHECK(c.shrunk_verdict == Verdict::refused);
  for (std::size_t i = 1; i < cases.size(); ++i) {
    CHECK(cases[i].shrunk_minimal);
    CHECK(cases[i].shrink_passes == 1);
  }
  for (const auto& p : cases) CHECK(std::filesystem::exists(dir.path() / p.corpus_file));
}

TEST_CASE("shrink stage: later passes go on with the pairs the first stopped by runs", "[experiments][shrink]") {
  TempDir dir;
  ShrinkStageOptions o;
  o.peer_options.peer_binary = stand_in(dir, "peer.sh", "[ $n -ge 9 ] && exit 3\nkill -SEGV $$");
  o.peer_options.timeout_s = 30;
  o.runs_per_pass = 5;
  o.max_passes = 50;
  o.seconds = 60;
  o.out_dir = dir.path().string();
  std::vector<PeerCase> cases = {failing_case(0, 24, Verdict::refused, 0.01),
                                 failing_case(1, 30, Verdict::refused, 0.01)};
  std::vector<ShrinkPair> pairs;
  for (auto& c : cases) pairs.push_back({&c, uniform(c.n, c.index + 1), "test", 0});
  const ShrinkStageResult r = run_shrink_stage(pairs, o);
  CHECK(r.pass_seconds.size() > 2);
  for (const PeerCase& c : cases) {
    CHECK(c.shrunk_minimal);
    CHECK(c.shrunk_points == 9);
    CHECK(c.shrink_passes > 2);
    CHECK(c.shrink_runs <= c.shrink_passes * o.runs_per_pass);
  }
}

TEST_CASE("shrink stage: a hang shrinks under a short limit and is confirmed under the full one",
          "[experiments][shrink]") {
  TempDir dir;
  ShrinkStageOptions o;
  o.peer_options.peer_binary = stand_in(dir, "peer.sh", "[ $n -ge 6 ] && exec sleep 60\nexit 3");
  o.peer_options.timeout_s = 1.5;
  o.seconds = 8;
  o.out_dir = dir.path().string();
  std::vector<PeerCase> cases = {failing_case(0, 12, Verdict::hung, 1.5)};
  std::vector<ShrinkPair> pairs = {{&cases[0], uniform(12, 1), "test", 0.5}};
  const auto t0 = std::chrono::steady_clock::now();
  const ShrinkStageResult r = run_shrink_stage(pairs, o);
  CHECK(seconds_since(t0) < o.seconds + 1);
  CHECK(r.reserved_seconds == Approx(3.5));  // the full limit and 2 s
  CHECK(r.confirm_seconds >= 1.5);  // the confirming run hung for the full limit
  const PeerCase& c = cases[0];
  CHECK(c.shrunk_minimal);
  CHECK(c.shrink_stop.empty());
  CHECK(c.shrunk_points == 6);
  CHECK(c.hung_try_seconds == Approx(0.5));
  CHECK(c.shrunk_verdict == Verdict::hung);
  CHECK(c.shrunk_run.wall_seconds >= 1.5);
  CHECK(c.shrink_note.empty());
  CHECK(std::filesystem::exists(dir.path() / c.corpus_file));
}

TEST_CASE("a hang whose shrunk input does not hang under the full limit keeps its original input",
          "[experiments][shrink]") {
  TempDir dir;
  // Slow (1 s) from 5 points on, hangs from 10: under a 0.5 s limit per try it
  // "hangs" on 5 points, which then answer (a refusal) under the full 2 s limit.
  PeerOptions o;
  o.peer_binary = stand_in(dir, "peer.sh", "[ $n -ge 10 ] && exec sleep 60\n[ $n -ge 5 ] && sleep 1\nexit 3");
  o.timeout_s = 2;
  const auto points = uniform(12, 1);
  PeerCase c = failing_case(0, 12, Verdict::hung, 2);
  shrink_and_save(c, points, o, {200, 0, 0.5}, dir.path().string(), "test");
  CHECK_FALSE(c.shrunk_minimal);
  CHECK(c.shrink_stop == "unconfirmed");
  CHECK(c.shrunk_points == 12);
  CHECK(c.shrunk_input == points);
  CHECK(c.shrunk_verdict == Verdict::hung);
  CHECK(c.shrink_note.find("shrunk to 5 points") != std::string::npos);
  CHECK(c.shrink_note.find("gave refused") != std::string::npos);

  // No confirming run when it could not end in the time left: the original is kept.
  PeerCase d = failing_case(1, 12, Verdict::hung, 2);
  shrink_pass(d, points, o, {200, 0, 0.5});
  REQUIRE(d.shrunk_points == 5);
  const std::size_t runs = d.shrink_runs;
  confirm_hang(d, points, o, 1.0);
  CHECK(d.shrink_runs == runs);
  CHECK(d.shrink_stop == "unconfirmed");
  CHECK(d.shrunk_points == 12);
  CHECK(d.shrink_note.find("no time left") != std::string::npos);
}

TEST_CASE("a hang's per-try limit", "[experiments][shrink]") {
  CHECK(hung_try_limit(0.05, 30) == 2);
  CHECK(hung_try_limit(0.5, 30) == 5);
  CHECK(hung_try_limit(10, 30) == 15);
}
