#pragma once
// `dtlab fuzz --target PEER`: a campaign that judges a peer instead of dtlab on the
// chosen fuzz families, a Delaunay peer (cgal, qhull, scipy, gmsh, ...:
// experiments/peer_campaign.hpp) or a Voronoi peer (voro++, scipy-voronoi, qvoronoi,
// cgal-dual, dtlab:B: experiments/voronoi_campaign.hpp). Failing cases are shrunk into
// <out>/corpus, each with the command that replays it; one row per family (cases,
// failing, verdicts) or --json. Exit 1 when the peer failed, 3 when it is not installed.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dtlab::cli {

struct TargetArgs {
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

int run_peer_target(const TargetArgs& a);
int run_voronoi_target(const TargetArgs& a);

}  // namespace dtlab::cli
