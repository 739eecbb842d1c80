#pragma once
// A campaign that judges one peer (oracle/peers.hpp) instead of dtlab: point sets x
// cases, each run in the peer's own process and judged by the exact checker; a
// failing case is shrunk by delta debugging (fuzz/shrink.hpp) to a smallest input
// with the same verdict and saved in <out>/corpus with the command that reproduces
// it. Behind `dtlab fuzz --target PEER` and the leaderboard experiment.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "oracle/peers.hpp"

namespace dtlab::experiments {

using PointGenerator = std::function<std::vector<Point3>(std::size_t n, std::uint64_t seed)>;

struct PointSource {
  std::string name;
  PointGenerator generate;
};

// Every fuzz family as a point source.
std::vector<PointSource> fuzz_family_sources(const std::vector<std::string>& names);

struct PeerCase {
  std::string peer, source;
  std::size_t index = 0;
  std::uint64_t seed = 0;  // the case seed (fuzz/case_seed.hpp)
  std::size_t n = 0;
  bool lower_dimensional = false;  // the input spans no volume: no tets is right
  PeerRun run;                     // its mesh dropped once judged
  std::string corpus_file;         // relative to out_dir; "" when not saved
  std::size_t shrunk_points = 0;
  bool shrunk_minimal = false;
  std::string shrink_stop;         // why it is not 1-minimal: "runs", "time" (budget spent),
                                   // "hung" (not shrunk: each try would cost the time limit)
  std::size_t shrink_runs = 0;     // peer runs the shrink made
  double shrink_seconds = 0;
  Verdict shrunk_verdict = Verdict::not_installed;  // the saved input run afresh
  bool failed() const;
};

// A peer fails a case when its verdict is not delaunay; on a lower-dimensional input a
// refusal or an empty answer is right too. not-installed is no failure (no run).
bool peer_failed(Verdict v, bool lower_dimensional);

struct PeerCampaignOptions {
  std::string peer;
  std::vector<std::string> peers;  // when not empty: each of these instead of `peer`,
                                   // peers x sources x cases in one work queue
  std::vector<PointSource> sources;
  std::size_t cases = 10;
  std::optional<std::size_t> only_case;          // run just this case index
  std::size_t min_points = 8, max_points = 64;  // n per case, from the case seed
  std::uint64_t seed = 1;
  std::string out_dir;          // corpus/ goes here; "" writes nothing
  bool shrink = true;
  std::size_t shrink_budget = 200;  // peer runs per shrunk case
  PeerOptions peer_options;
  unsigned jobs = 1;
  std::function<void(const PeerCase&)> on_case;  // after each case, under a lock
};

std::vector<PeerCase> run_peer_campaign(const PeerCampaignOptions& options);

struct ShrinkBudget {
  std::size_t runs = 200;  // peer runs at most
  double seconds = 0;      // wall clock at most; 0: no limit
};

// Shrinks `points` (on which c.peer gave c.run.verdict) to a smallest subset with the
// same verdict that still spans a volume (if `points` did), and writes
// <out_dir>/corpus/<stem>.node + .json; fills c's corpus_file, shrunk_* and shrink_*
// fields. The tries run the slow-start peers in served helpers (PeerOptions::servers),
// each under a time limit of 10x the original run's (2 s at least, options.timeout_s at
// most); a shrunk input is judged once more in a fresh process (shrunk_verdict; an
// unshrunk one keeps the verdict of its fresh run). A hung case is saved unshrunk.
// `servers`: the served helpers to use (kept by the caller across shrinks, one set per
// thread); nullptr: the shrink's own.
void shrink_and_save(PeerCase& c, const std::vector<Point3>& points, const PeerOptions& options,
                     ShrinkBudget budget, const std::string& out_dir, const std::string& original_command,
                     ServedChildren* servers = nullptr);

}  // namespace dtlab::experiments
