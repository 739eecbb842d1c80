#include "oracle/peers/peer_json.hpp"

#include <cstdio>

namespace dtlab {

nlohmann::json to_json(const PeerRun& r) {
  nlohmann::json j;
  j["verdict"] = verdict_name(r.verdict);
  j["message"] = r.message;
  j["seconds"] = r.seconds;
  j["wall_seconds"] = r.wall_seconds;
  j["peak_rss_bytes"] = r.peak_rss_bytes;
  if (r.mesh) j["tets"] = r.mesh->tets.size();
  j["unused"] = r.unused.size();
  j["extra_vertices"] = r.extra_vertices;
  j["extra_tets"] = r.extra_tets;
  j["collapsed_tets"] = r.collapsed_tets;
  nlohmann::json d = nlohmann::json::object();
  if (r.report)
    for (int k = 0; k < kDefectKinds; ++k)
      if (r.report->counts[k]) d[defect_name(static_cast<DefectKind>(k))] = r.report->counts[k];
  j["defects"] = d;
  if (r.report) j["check_seconds"] = r.report->stats.seconds;
  return j;
}

std::string peer_line(const PeerRun& r) {
  char buf[160];
  if (no_answer(r.verdict)) {
    std::snprintf(
        buf, sizeof buf, "%-15s %10s  %9s  %8s", verdict_name(r.verdict), "-",
        r.verdict == Verdict::not_installed ? "-" : (std::to_string(r.wall_seconds).substr(0, 6) + " s").c_str(), "-");
    return std::string(buf) + "  " + r.message;
  }
  std::snprintf(buf, sizeof buf, "%-15s %10zu  %7.3f s  %5.0f MB", verdict_name(r.verdict),
                r.mesh ? r.mesh->tets.size() : std::size_t{0}, r.seconds, r.peak_rss_bytes / 1e6);
  std::string s = buf;
  std::string detail = r.report ? defect_counts_text(*r.report) : "";
  if (r.extra_tets)
    detail = std::to_string(r.extra_tets) + " tets on " + std::to_string(r.extra_vertices) +
             " vertices that are no input point" + (detail.empty() ? "" : "; " + detail);
  if (!r.message.empty()) detail += (detail.empty() ? "" : "; ") + r.message;
  if (!detail.empty()) s += "  " + detail;
  return s;
}

}  // namespace dtlab
