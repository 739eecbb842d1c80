#pragma once
// One `dtlab oracle` run as a library call, shared by the CLI and the Python module:
// build ours, run each peer in its own process, judge every answer with the exact
// checker, and compare ours canonically with every peer whose answer is proven
// Delaunay. A peer that gave no answer, or a wrong one, is "not compared", never
// "agree".
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "kernel/build.hpp"
#include "oracle/check/compare.hpp"
#include "oracle/peers/peers.hpp"

namespace dtlab {

// Exit codes of an oracle session (the CLI's): ours proven and agreeing with every
// proven peer; ours wrong or differing; some requested peer gave no answer.
enum OracleExit : int { oracle_ok = 0, oracle_defect = 1, oracle_no_answer = 3 };

struct OracleSessionOptions {
  std::vector<std::string> against = {"cgal", "tetgen"};  // peer names, or "all"
  PredicateSpec predicates;                               // our backend
  BuildOptions build;                                     // our boundary, insertion order, seed
  PeerOptions peers;
  // Called before each peer runs (name, peers done, peers in all): progress of long runs.
  std::function<void(const std::string&, std::size_t, std::size_t)> progress;
  // Called after each peer's run is judged (the run, peers done, peers in all).
  std::function<void(const PeerRun&, std::size_t, std::size_t)> on_peer;
};

struct OracleSession {
  struct Compared {
    std::size_t peer;  // index into peers
    Comparison comparison;
  };
  BuildResult built;
  CheckReport ours;
  bool ours_ok = false;  // built without failure and proven Delaunay
  std::vector<PeerRun> peers;
  std::vector<Compared> compared;
  std::vector<std::string> not_compared, problems;
  int exit = oracle_ok;
};

// Throws std::invalid_argument for an unknown peer name and for input that spans no
// volume (fewer than 4 points, all coplanar: the CLI's exit 2). This thread's progress
// listener (kernel/progress.hpp) hears our build ("insert") and our check ("check"),
// not the checks of the peers' answers.
OracleSession run_oracle_session(std::span<const Point3> points, const OracleSessionOptions& options);

// {ok, exit, problems, not_compared, dtlab: {verdict, seconds, tets, duplicates,
//  failure?, check}, peers: {name: peer json + agree?}, comparisons: {"dtlab vs P": ...}}
nlohmann::json to_json(const OracleSession& session);

// The line `dtlab oracle` prints for a comparison ("agree (identical tets; ...)").
std::string comparison_text(const Comparison& c);

}  // namespace dtlab
