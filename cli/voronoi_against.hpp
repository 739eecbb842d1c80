#pragma once
// `dtlab voronoi INPUT --against PEERS`: our cells and every peer's, clipped to the
// same box, judged by the exact Voronoi checker (voronoi_check/). Exit codes as the
// oracle's: 0 ours exact and every peer answered, 1 ours not exact, 3 ours exact but
// some peer gave no answer (crashed, hung, refused, not installed).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "voronoi/voronoi.hpp"

namespace dtlab::cli {

struct VoronoiAgainst {
  std::vector<std::string> peers;  // expanded names
  double timeout = 600;
  bool quiet = false;
};

// Parses "none" | "all" | a comma list; throws CLI::ValidationError naming an unknown peer.
std::vector<std::string> parse_voronoi_peers(const std::string& list);

// Judges ours (`diagram`) and each peer; fills `out` ({"dtlab": ..., "peers": {name:
// {...}}}) and prints one line per peer unless `json`. Returns the exit code.
int judge_voronoi_peers(const std::vector<Point3>& sites, const VoronoiDiagram& diagram, const VoronoiAgainst& a,
                        bool json, nlohmann::json& out);

}  // namespace dtlab::cli
