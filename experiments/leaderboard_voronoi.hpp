#pragma once
// The leaderboard's Voronoi section: every Voronoi peer (voronoi_check/voronoi_peers.hpp)
// on the DT leaderboard's point sources and sizes, judged by the exact Voronoi checker
// (experiments/voronoi_campaign.hpp); per (peer, source) verdict counts with Wilson
// intervals, the first failure of each failing pair shrunk and saved in corpus/, and a
// speed table (the peer's cells, the check of them). Writes data/voronoi.csv,
// data/voronoi_speed.csv and voronoi/corpus/; returns the report's Markdown section and its facts.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/peer_campaign.hpp"

namespace dtlab::experiments {

struct VoronoiBoardOptions {
  std::vector<std::string> peers;  // expanded Voronoi peer names
  std::vector<PointSource> sources;
  std::vector<std::size_t> family_sizes, mesh_sizes;  // sizes of fuzz families, of the others
  std::size_t families = 0;                           // sources[0, families) are fuzz families
  std::size_t cases = 3;                              // seeds per (source, size)
  std::uint64_t seed = 1;
  unsigned jobs = 2;
  double timeout_s = 30;
  std::size_t shrink_runs = 300;  // peer runs per shrunk pair
  double shrink_seconds = 300;    // the shrink stage's wall clock
  std::vector<PointSource> speed_sources;
  std::vector<std::size_t> speed_sizes;
  std::string out_dir;  // data/voronoi*.csv go here, shrunk inputs in out_dir/voronoi/corpus
};

struct VoronoiBoard {
  std::string markdown;
  nlohmann::json facts;
};

VoronoiBoard run_voronoi_board(const VoronoiBoardOptions& options);

}  // namespace dtlab::experiments
