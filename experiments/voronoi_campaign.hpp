#pragma once
// A campaign that judges Voronoi peers (voronoi_check/voronoi_peers.hpp): point
// sources x cases, each peer in its own process, its cells clipped to the default box
// of the points (the bounding box grown by 0.1 per side, as `dtlab voronoi`) and
// judged by the exact Voronoi checker. A failing case is shrunk by delta debugging
// (fuzz/shrink.hpp) to a 1-minimal subset with the same verdict (each try judged in a
// fresh process, in the default box of the subset) and saved in <out>/corpus as a
// .node with a .json sidecar whose command replays it (`dtlab voronoi FILE --against
// PEER`). Behind `dtlab fuzz --target voro++` and the leaderboard's Voronoi section.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "experiments/case_grid.hpp"
#include "voronoi_check/voronoi_peers.hpp"

namespace dtlab::experiments {

// A peer fails on a verdict other than exact-topology and rounded-topology (floating
// tools cannot represent faces far below their rounding); not-installed is no run.
bool voronoi_failed(VoronoiVerdict v);

struct VoronoiCase {
  std::string peer, source;
  std::size_t index = 0;
  std::uint64_t seed = 0;  // the case seed (fuzz/case_seed.hpp)
  std::size_t n = 0;
  std::string not_judged;  // why the checker cannot judge it (coplanar or fewer than 4
                           // distinct sites, a box that overflows); "" when judged
  VoronoiPeerRun run;
  std::string corpus_file;  // relative to out_dir; "" when not saved
  std::size_t shrunk_points = 0;
  bool shrunk_minimal = false;
  std::string shrink_stop;      // why not 1-minimal: "runs" (budget spent), "hung" (saved unshrunk)
  std::size_t shrink_runs = 0;  // peer runs the shrink made
  double shrink_seconds = 0;
  VoronoiVerdict shrunk_verdict = VoronoiVerdict::not_installed;  // the saved input judged afresh
  bool failed() const { return not_judged.empty() && voronoi_failed(run.verdict); }
};

// Runs `peer` on `points` in their default box; an input the checker cannot judge is
// not run (not_judged says why).
VoronoiCase run_voronoi_case(const std::string& peer, const std::vector<Point3>& points,
                             const VoronoiPeerOptions& options);

// Shrinks c's failing input `points` (at most `runs` peer runs; a hang is saved
// unshrunk) and writes <out_dir>/corpus/<peer>-<source>-n<N>-<case>.node and .json.
// `original_command` reproduces the unshrunk case.
void shrink_and_save_voronoi(VoronoiCase& c, const std::vector<Point3>& points, const VoronoiPeerOptions& options,
                             std::size_t runs, const std::string& out_dir, const std::string& original_command);

// shrink: every failing case (false: none; the leaderboard shrinks one per pair).
struct VoronoiCampaignOptions : CaseGrid {
  std::vector<std::string> peers;
  VoronoiPeerOptions peer_options;
  std::function<void(const VoronoiCase&)> on_case;  // after each case, under a lock
};

// peers x sources x cases in one work queue, in that order in the result.
std::vector<VoronoiCase> run_voronoi_campaign(const VoronoiCampaignOptions& options);

}  // namespace dtlab::experiments
