#pragma once
// A campaign that judges one peer (oracle/peers/peers.hpp) instead of dtlab: point sets x
// cases, each run in the peer's own process and judged by the exact checker; a
// failing case is shrunk by delta debugging (fuzz/shrink.hpp) to a smallest input
// with the same verdict and saved in <out>/corpus with the command that reproduces
// it. Behind `dtlab fuzz --target PEER` and the leaderboard experiment.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "experiments/case_grid.hpp"
#include "fuzz/shrink.hpp"
#include "oracle/peers/peers.hpp"

namespace dtlab::experiments {

struct PeerCase {
  std::string peer, source;
  std::size_t index = 0;
  std::uint64_t seed = 0;  // the case seed (fuzz/case_seed.hpp)
  std::size_t n = 0;
  bool lower_dimensional = false;  // the input spans no volume: no tets is right
  PeerRun run;                     // its mesh dropped once judged
  std::string corpus_file;         // relative to out_dir; "" when not saved
  std::vector<Point3> shrunk_input;  // the smallest failing input so far (a later pass goes on from it)
  std::size_t shrunk_points = 0;
  fuzz::ShrinkPosition shrink_position;  // where the shrinker stopped (the next pass resumes there)
  bool shrunk_minimal = false;
  std::string shrink_stop;         // why it is not 1-minimal: "runs", "time" (budget spent),
                                   // "hung" (a hang not shrunk: each try would cost the time limit),
                                   // "unconfirmed" (a hang shrunk under the short limit whose
                                   // input did not hang under the full one: the original saved)
  std::string shrink_note;         // what "unconfirmed" means for this case
  std::size_t shrink_passes = 0;   // shrink passes it took part in
  std::size_t shrink_runs = 0;     // peer runs the shrink made, all passes
  std::size_t shrink_tests = 0;    // shrinker predicate calls, all passes
  double shrink_seconds = 0;       // wall clock, all passes and the confirming run
  double hung_try_seconds = 0;     // a hang's shrink: the per-try limit ("exceeded" = still hung)
  std::size_t served_not_reproduced = 0;  // points of a served shrink a fresh run disagreed with
  Verdict shrunk_verdict = Verdict::not_installed;  // the saved input run afresh
  PeerRun shrunk_run;              // that run (mesh dropped)
  bool failed() const;
};

// A peer fails a case when its verdict is not delaunay; on a lower-dimensional input a
// refusal or an empty answer is right too. not-installed is no failure (no run).
bool peer_failed(Verdict v, bool lower_dimensional);

struct PeerCampaignOptions : CaseGrid {
  std::string peer;
  std::vector<std::string> peers;  // when not empty: each of these instead of `peer`,
                                   // peers x sources x cases in one work queue
  PeerOptions peer_options;
  std::function<void(const PeerCase&)> on_case;  // after each case, under a lock
};

std::vector<PeerCase> run_peer_campaign(const PeerCampaignOptions& options);

struct ShrinkBudget {
  std::size_t runs = 200;        // peer runs at most (in one pass)
  double seconds = 0;            // wall clock at most; 0: no limit
  double hung_try_seconds = 0;   // a hung case: the per-try limit; 0: a hang is saved unshrunk
};

// One shrink pass over the failing input of c (on which c.peer gave c.run.verdict),
// from `original` or, when an earlier pass left one, from c.shrunk_input: delta
// debugging to a smaller subset with the same verdict that still spans a volume (if
// `original` did), within `budget`. Fills c's shrunk_* and shrink_* fields (counts add
// up over passes). Tries run the slow-start peers in served helpers (`servers`, kept by
// the caller; nullptr: the pass's own), each under a limit of 10x the original run's
// (2 s at least, options.timeout_s at most) cut to the time the budget has left: a try
// cut short ends the pass as out of time. A shrunk input is judged once more in a fresh
// process (shrunk_run); when that disagrees with a served shrink, the pass shrinks
// again with fresh processes in what is left of its budget.
// A hung case shrinks under budget.hung_try_seconds per try, a try that exceeds it
// counting as still hung; its shrunk input is confirmed afterwards (confirm_hang).
void shrink_pass(PeerCase& c, const std::vector<Point3>& original, const PeerOptions& options, ShrinkBudget budget,
                 ServedChildren* servers = nullptr);

// A hang shrunk under the short limit, run once more in a fresh process under the full
// one (options.timeout_s): kept when it hangs there too; else, or when `seconds_left`
// is shorter than that limit (no confirming run is started then), the original input
// (which hung so in the counted run) is what is saved: shrink_stop "unconfirmed" and
// shrink_note say why. No-op for a case that is not a shrunk hang.
void confirm_hang(PeerCase& c, const std::vector<Point3>& original, const PeerOptions& options,
                  double seconds_left);

// Writes c.shrunk_input to <out_dir>/corpus/<stem>.node with a .json sidecar (the
// reproducing command, how the shrink ended) and sets c.corpus_file.
void save_shrunk(PeerCase& c, std::size_t original_points, const std::string& out_dir,
                 const std::string& original_command);

// One pass, the hang's confirmation and the files: a single case's whole shrink.
void shrink_and_save(PeerCase& c, const std::vector<Point3>& points, const PeerOptions& options,
                     ShrinkBudget budget, const std::string& out_dir, const std::string& original_command,
                     ServedChildren* servers = nullptr);

}  // namespace dtlab::experiments
