#include "experiments/voronoi_campaign.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "fuzz/campaign.hpp"
#include "fuzz/case_seed.hpp"
#include "fuzz/outcome.hpp"
#include "fuzz/shrink.hpp"
#include "fuzz/work_queue.hpp"
#include "kernel/output_file.hpp"
#include "kernel/point_io.hpp"
#include "voronoi/voronoi.hpp"
#include "voronoi_check/check_json.hpp"
#include "voronoi_check/voronoi_peer_command.hpp"

namespace dtlab::experiments {

namespace fs = std::filesystem;

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
    tries.timeout_s = std::clamp(10 * c.run.wall_seconds, std::min(2.0, options.timeout_s), options.timeout_s);
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
  const fs::path dir = fs::path(out_dir) / "corpus";
  fs::create_directories(dir);
  std::string stem = c.peer + "-" + c.source + "-n" + std::to_string(c.n) + "-" + std::to_string(c.index);
  std::replace(stem.begin(), stem.end(), ':', '_');
  std::replace(stem.begin(), stem.end(), '+', 'p');
  write_node((dir / (stem + ".node")).string(), shrunk);
  c.corpus_file = "corpus/" + stem + ".node";
  nlohmann::json j = {
      {"peer", c.peer},
      {"file", c.corpus_file},
      {"source", c.source},
      {"case", c.index},
      {"case_seed", c.seed},
      {"points_original", points.size()},
      {"points", shrunk.size()},
      {"verdict", voronoi_verdict_name(target)},
      {"message", c.run.message},
      {"shrink_runs", c.shrink_runs},
      {"shrink_seconds", c.shrink_seconds},
      {"minimal", c.shrunk_minimal},
      {"shrink_stopped_by", c.shrink_stop},
      {"shrunk_verdict_fresh", voronoi_verdict_name(c.shrunk_verdict)},
      {"command", "dtlab voronoi " + c.corpus_file + " --against " + c.peer +
                      voronoi_peer_definition_arguments(c.peer) + " --json"},
      {"original_command", original_command},
  };
  if (c.run.report) j["original_report"] = to_json(*c.run.report);
  write_text_file((dir / (stem + ".json")).string(), j.dump(2) + "\n");
}

std::vector<VoronoiCase> run_voronoi_campaign(const VoronoiCampaignOptions& o) {
  struct Work {
    const std::string* peer;
    const PointSource* source;
    std::size_t index;
  };
  std::vector<Work> work;
  for (const std::string& p : o.peers)
    for (const PointSource& s : o.sources)
      for (std::size_t i = 0; i < o.cases; ++i)
        if (!o.only_case || *o.only_case == i) work.push_back({&p, &s, i});
  std::vector<VoronoiCase> results(work.size());
  std::mutex lock;
  fuzz::run_work_queue(work.size(), o.jobs, [&](std::size_t w) {
    const std::uint64_t seed = fuzz::case_seed(o.seed, work[w].source->name, work[w].index);
    const std::size_t n = fuzz::case_points(seed, o.min_points, o.max_points);
    const std::vector<Point3> points = work[w].source->generate(n, seed);
    VoronoiCase c = run_voronoi_case(*work[w].peer, points, o.peer_options);
    c.source = work[w].source->name;
    c.index = work[w].index;
    c.seed = seed;
    if (c.failed() && o.shrink && !o.out_dir.empty()) {
      const std::string cmd = "dtlab fuzz --target " + c.peer + " --family " + c.source + " --case " +
                              std::to_string(c.index) + " --seed " + std::to_string(o.seed) + " --min-points " +
                              std::to_string(o.min_points) + " --points " + std::to_string(o.max_points) +
                              " --out DIR" + voronoi_peer_definition_arguments(c.peer);
      shrink_and_save_voronoi(c, points, o.peer_options, o.shrink_budget, o.out_dir, cmd);
    }
    if (c.run.report) c.run.report->witnesses.clear();  // counts and largest faces kept
    std::lock_guard<std::mutex> g(lock);
    if (o.on_case) o.on_case(c);
    results[w] = std::move(c);
  });
  return results;
}

}  // namespace dtlab::experiments
