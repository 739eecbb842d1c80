#include "experiments/voronoi_campaign.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "fuzz/outcome.hpp"
#include "fuzz/shrink.hpp"
#include "voronoi/voronoi.hpp"
#include "voronoi_check/check_json.hpp"
#include "voronoi_check/voronoi_peer_command.hpp"

namespace dtlab::experiments {

bool voronoi_failed(VoronoiVerdict v) {
  return v != VoronoiVerdict::exact_topology && v != VoronoiVerdict::rounded_topology &&
         v != VoronoiVerdict::not_installed;
}

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Why the exact checker cannot judge these sites in their default box, or "".
std::string why_not_judged(const std::vector<Point3>& points) {
  if (fuzz::is_lower_dimensional(points)) return "coplanar or fewer than 4 distinct sites";
  for (const auto& p : points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return "a site is not finite";
  const vor::Box b = default_box(points, 0.1);
  for (double v : {b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z})
    if (!std::isfinite(v)) return "the default box overflows";
  if (!std::isfinite(b.volume()) || !(b.volume() > 0)) return "the default box's volume overflows";
  return "";
}

VoronoiPeerRun judged_run(const std::string& peer, const std::vector<Point3>& points, const VoronoiPeerOptions& o,
                          std::string& not_judged) {
  VoronoiPeerRun run;
  run.name = peer;
  not_judged = why_not_judged(points);
  if (!not_judged.empty()) return run;
  try {
    return run_voronoi_peer(peer, points, default_box(points, 0.1), o);
  } catch (const std::invalid_argument& e) {  // the checker refused the sites
    not_judged = e.what();
    return run;
  }
}

}  // namespace

VoronoiCase run_voronoi_case(const std::string& peer, const std::vector<Point3>& points,
                             const VoronoiPeerOptions& options) {
  VoronoiCase c;
  c.peer = peer;
  c.n = points.size();
  c.run = judged_run(peer, points, options, c.not_judged);
  return c;
}

void shrink_and_save_voronoi(VoronoiCase& c, const std::vector<Point3>& points, const VoronoiPeerOptions& options,
                             std::size_t runs, const std::string& out_dir, const std::string& original_command) {
  const auto t0 = Clock::now();
  const VoronoiVerdict target = c.run.verdict;
  std::vector<Point3> shrunk = points;
  if (target == VoronoiVerdict::hung) {
    c.shrink_stop = "hung";  // each try would cost the whole time limit
    c.shrunk_verdict = target;
  } else {
    VoronoiPeerOptions tries = options;
    tries.timeout_s = shrink_try_limit(c.run.wall_seconds, options.timeout_s);
    const auto fails = [&](const std::vector<Point3>& candidate) {
      ++c.shrink_runs;
      std::string why;
      const VoronoiPeerRun r = judged_run(c.peer, candidate, tries, why);
      return why.empty() && r.verdict == target;
    };
    fuzz::ShrinkResult s = fuzz::shrink_points(points, fails, runs);
    shrunk = std::move(s.points);
    c.shrunk_minimal = s.minimal;
    c.shrink_stop = s.minimal ? "" : "runs";
    std::string why;
    c.shrunk_verdict = judged_run(c.peer, shrunk, options, why).verdict;  // afresh, under the full limit
    ++c.shrink_runs;
  }
  c.shrunk_points = shrunk.size();
  c.shrink_seconds = seconds_since(t0);
  const std::string stem = corpus_stem(c.peer, c.source, c.n, c.index);
  c.corpus_file = save_corpus_points(out_dir, stem, shrunk);
  nlohmann::json j =
      case_sidecar(c, points.size(), shrunk.size(),
                   "dtlab voronoi " + c.corpus_file + " --against " + c.peer +
                       voronoi_peer_definition_arguments(c.peer) + " --json",
                   original_command);
  j["verdict"] = voronoi_verdict_name(target);
  j["message"] = c.run.message;
  j["shrunk_verdict_fresh"] = voronoi_verdict_name(c.shrunk_verdict);
  if (c.run.report) j["original_report"] = to_json(*c.run.report);
  save_corpus_sidecar(out_dir, stem, j);
}

std::vector<VoronoiCase> run_voronoi_campaign(const VoronoiCampaignOptions& o) {
  if (!o.out_dir.empty()) remove_grid_corpus(o.peers, o);
  return run_grid<VoronoiCase>(
      o.peers, o,
      [&](VoronoiCase& c, const std::vector<Point3>& points) {
        c.run = judged_run(c.peer, points, o.peer_options, c.not_judged);
        if (c.failed() && o.shrink && !o.out_dir.empty())
          shrink_and_save_voronoi(c, points, o.peer_options, o.shrink_budget, o.out_dir,
                                  grid_case_command(c.peer, o, c.source, c.index) +
                                      voronoi_peer_definition_arguments(c.peer));
        if (c.run.report) c.run.report->witnesses.clear();  // counts and largest faces kept
      },
      o.on_case);
}

}  // namespace dtlab::experiments
