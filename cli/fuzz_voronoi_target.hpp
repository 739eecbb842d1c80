#pragma once
// `dtlab fuzz --target VORONOI_PEER` (voro++, scipy-voronoi, qvoronoi, cgal-dual,
// dtlab:B): the Voronoi campaign (experiments/voronoi_campaign.hpp) on the chosen
// fuzz families; failing cases shrunk to 1-minimal into <out>/corpus, each with the
// `dtlab voronoi` command that replays it. Exit 1 when the peer failed, 3 when it is
// not installed.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dtlab::cli {

struct VoronoiTargetArgs {
  std::string target;
  std::vector<std::string> families;
  std::size_t cases = 100;
  std::optional<std::size_t> only_case;
  std::uint64_t seed = 1;
  std::size_t min_points = 8, max_points = 64;
  std::string out;
  bool shrink = true;
  std::size_t shrink_budget = 500;
  unsigned jobs = 1;
  bool json = false, quiet = false;
};

int run_voronoi_target(const VoronoiTargetArgs& a);

}  // namespace dtlab::cli
