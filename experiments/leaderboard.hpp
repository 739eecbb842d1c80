#pragma once
// `dtlab experiment leaderboard`: which Delaunay code can you trust? Every peer
// (oracle/peers/peers.hpp) on every fuzz family and on samples of CGAL's demo meshes, at
// several sizes and seeds, each answer judged by the exact checker against the input;
// failures shrunk to small reproducible inputs; a speed table against CGAL.
// Writes leaderboard.csv, report.md/.html, environment.json, corpus/ and data/.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "experiments/thesis_failures.hpp"

namespace dtlab::experiments {

struct LeaderboardOptions {
  std::filesystem::path out = "reports/leaderboard";
  bool quick = false;                      // 2 cases per cell, n = 48 and 3000, speed at 10^4, short shrinks
  std::vector<std::string> peers = {"all"};
  std::size_t cases = 0;                   // seeds per (source, size); 0: 2 quick, 3 otherwise
  std::uint64_t seed = 1;
  unsigned jobs = 2;
  double timeout_s = 0;                    // per peer run; 0: 10 s quick, 30 s otherwise
  std::vector<std::string> families;       // fuzz families; empty: all
  bool meshes = true;                      // CGAL demo mesh samples
  std::string cgal_data;                   // CGAL demo data.tar.gz; "": the libcgal-demo one
  std::size_t shrink_runs = 0;             // peer runs per shrunk (peer, source) and pass; 0: 48 quick, 300 otherwise
  double shrink_seconds = 0;               // the shrink stage's wall-clock budget; 0: 30 s quick, 600 otherwise
  std::size_t speed_n = 0;                 // one size for the speed table; 0: 10^4 quick, else 10^5 and 10^6
  std::vector<std::string> voronoi_peers = {"all"};  // the Voronoi section's peers; {"none"}: left out
  std::vector<std::size_t> voronoi_speed_sizes;     // empty: 10^4 quick, else 10^5 (10^6 when asked)
  bool progress = false;
  std::string command_line;
};

// Exit 1 when a dtlab robust backend (dtlab:adaptive, dtlab:exact) failed a case.
ExperimentResult run_leaderboard(const LeaderboardOptions& options);

}  // namespace dtlab::experiments
