#pragma once
// The leaderboard's shrink stage: the first failing input of each (peer, source)
// shrunk by delta debugging (experiments/peer_campaign.hpp) under one wall-clock
// budget for the whole stage, in passes. Pass one gives each pair, as it starts, the
// time left times the jobs over the pairs left; every later pass gives what is left
// to the pairs the one before stopped by time or by its run budget, each going on
// from its smallest failing input so far, while time is left and a pass gets
// somewhere. Hangs shrink under a short per-try limit and are confirmed under the
// full one at the end, in time the passes leave for it; then every pair's input is
// saved in <out_dir>/corpus.
#include <cstddef>
#include <string>
#include <vector>

#include "experiments/peer_campaign.hpp"

namespace dtlab::experiments {

struct ShrinkPair {
  PeerCase* failure = nullptr;  // the failing case; its shrink fields get filled
  std::vector<Point3> points;   // its input
  std::string command;          // what reproduces it (for the sidecar)
  double hung_try_seconds = 0;  // a hang: the per-try limit of its shrink; 0: saved unshrunk
};

struct ShrinkStageOptions {
  double seconds = 300;             // wall clock for the whole stage, confirmations included
  std::size_t runs_per_pass = 300;  // peer runs per pair and pass
  unsigned jobs = 2;                // pairs at a time
  std::size_t max_passes = 1000;   // a safety net: passes end when time is up or one gets nowhere
  PeerOptions peer_options;         // its timeout_s is the full limit a hang is confirmed under
  std::string out_dir;
};

struct ShrinkStageResult {
  std::vector<double> pass_seconds;  // wall seconds of each pass
  std::vector<std::size_t> pass_pairs;  // pairs each pass shrank
  double reserved_seconds = 0;       // kept back from the passes for confirming hangs
  double confirm_seconds = 0;
  double seconds = 0;
};

// The hung shrink's per-try limit: 10x the slowest run of the peer on that source
// that did not hang, 2 s at least, half the full limit at most.
double hung_try_limit(double slowest_answered_seconds, double full_limit_seconds);

ShrinkStageResult run_shrink_stage(std::vector<ShrinkPair>& pairs, const ShrinkStageOptions& options);

}  // namespace dtlab::experiments
