#include "cli/voronoi_against.hpp"

#include <cstdio>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli/command.hpp"
#include "cli/progress.hpp"
#include "voronoi_check/check_json.hpp"
#include "voronoi_check/voronoi_peers.hpp"

namespace dtlab::cli {

namespace {

constexpr int kNoAnswer = 3;

std::string line_of(const VoronoiPeerRun& r) {
  std::ostringstream s;
  s << r.name << ": " << voronoi_verdict_name(r.verdict);
  if (r.report) {
    const auto text = voronoi_counts_text(*r.report);
    if (!text.empty()) s << " (" << text << ")";
    if (r.report->largest_wrong_face > 0)
      s << ", largest wrong face " << r.report->largest_wrong_face << " of extent^2";
    if (r.report->largest_small_face > 0) s << ", largest small face " << r.report->largest_small_face;
    s << ", vertices within " << r.report->max_vertex_ulps << " ulps";
    const auto& t = r.report->tolerances;
    if (t.vertex.ulps || t.convex.ulps || t.small_face.ulps || t.volume.ulps)
      s << " (tolerances by the ulp floor, one ulp " << t.ulp << ")";
  }
  if (!r.message.empty()) s << ": " << r.message;
  s << ", " << r.seconds << " s";
  return s.str();
}

}  // namespace

std::vector<std::string> parse_voronoi_peers(const std::string& list) {
  if (list == "none" || list.empty()) return {};
  std::vector<std::string> names;
  std::stringstream in(list);
  for (std::string n; std::getline(in, n, ',');)
    if (!n.empty()) names.push_back(n);
  try {
    return expand_voronoi_peer_names(names);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--against", e.what());
  }
}

int judge_voronoi_peers(const std::vector<Point3>& sites, const VoronoiDiagram& diagram, const VoronoiAgainst& a,
                        bool json, nlohmann::json& out) {
  VoronoiPeerOptions o;
  o.timeout_s = a.timeout;
  o.check.dt = diagram.dt;  // null unless our DT came from exact predicates: then built by the checker
  o.check.relation = voronoi_relation(sites, o.check);  // one relation for ours and every peer
  const VoronoiCheckReport ours = check_voronoi(sites, diagram.box, tool_cells_of(diagram), o.check);
  out["exact_check"] = to_json(ours);
  if (!json) {
    const std::string counts = voronoi_counts_text(ours);
    std::printf("dtlab: %s%s\n", voronoi_verdict_name(ours.verdict),
                counts.empty() ? "" : (" (" + counts + ")").c_str());
  }
  out["peers"] = nlohmann::json::object();
  bool all_answered = true;
  Progress progress("voronoi", a.quiet);
  for (std::size_t k = 0; k < a.peers.size(); ++k) {
    progress.update("peers", k, a.peers.size(), "running " + a.peers[k]);
    const VoronoiPeerRun r = run_voronoi_peer(a.peers[k], sites, diagram.box, o);
    all_answered &= r.report.has_value();
    nlohmann::json j = r.report ? to_json(*r.report) : nlohmann::json::object();
    j["verdict"] = voronoi_verdict_name(r.verdict);  // also when there is no report
    j["message"] = r.message;
    j["seconds"] = r.seconds;
    j["wall_seconds"] = r.wall_seconds;
    j["peak_rss_bytes"] = r.peak_rss_bytes;
    j["version"] = voronoi_peer_version(a.peers[k], o);
    out["peers"][a.peers[k]] = j;
    if (!json) std::printf("%s\n", line_of(r).c_str());
  }
  // Rounded topology is the best doubles can hold (faces below the small-face fraction).
  if (ours.verdict != VoronoiVerdict::exact_topology && ours.verdict != VoronoiVerdict::rounded_topology)
    return kDefect;
  return all_answered ? kOk : kNoAnswer;
}

}  // namespace dtlab::cli
