#pragma once
// A peer's run as JSON and as one line of text, shared by `dtlab oracle` and the
// leaderboard experiment.
#include <nlohmann/json.hpp>
#include <string>

#include "oracle/peers/peers.hpp"

namespace dtlab {

// {verdict, message, tets, seconds, wall_seconds, peak_rss_bytes, unused,
//  extra_vertices, extra_tets, collapsed_tets, defects: {kind: count}}
nlohmann::json to_json(const PeerRun& run);

// "invalid  67 123 tets  0.412 s  81.2 MB  overlap 3, gap 1": verdict, tets,
// seconds, peak memory, then the defect counts or the peer's message.
std::string peer_line(const PeerRun& run);

}  // namespace dtlab
