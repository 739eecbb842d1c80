#include "experiments/leaderboard_voronoi.hpp"

#include <chrono>
#include <map>
#include <sstream>
#include <utility>

#include "experiments/csv_writer.hpp"
#include "experiments/report.hpp"
#include "experiments/voronoi_campaign.hpp"
#include "experiments/wilson_interval.hpp"
#include "voronoi/voronoi.hpp"
#include "voronoi_check/voronoi_neighbors.hpp"

namespace dtlab::experiments {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string percent(double v) { return fmt("%.0f%%", 100 * v); }

struct Tally {
  std::size_t cases = 0, failing = 0, not_judged = 0;
  std::map<std::string, std::size_t> verdicts;  // every judged verdict
  VoronoiCase* shrunk = nullptr;                // the saved failing input
};

struct SpeedRow {
  std::string source;
  std::size_t n = 0;
  VoronoiPeerRun run;
  double relation_s = 0, relation_dt_s = 0;  // the exact relation, built once per (source, n) for every peer
  double check_s() const { return run.report ? run.report->seconds + relation_s : 0; }
};

// Stage 1: peers x sources x cases at every size, none shrunk yet.
std::vector<VoronoiCase> run_cases(const VoronoiBoardOptions& o) {
  std::vector<VoronoiCase> all;
  const auto run = [&](std::vector<PointSource> sources, std::size_t n) {
    if (sources.empty()) return;
    VoronoiCampaignOptions c;
    c.peers = o.peers;
    c.sources = std::move(sources);
    c.cases = o.cases;
    c.min_points = c.max_points = n;
    c.seed = o.seed;
    c.shrink = false;
    c.peer_options.timeout_s = o.timeout_s;
    c.jobs = o.jobs;
    for (auto& k : run_voronoi_campaign(c)) all.push_back(std::move(k));
  };
  const std::vector<PointSource> fams(o.sources.begin(), o.sources.begin() + static_cast<std::ptrdiff_t>(o.families));
  const std::vector<PointSource> rest(o.sources.begin() + static_cast<std::ptrdiff_t>(o.families), o.sources.end());
  for (auto n : o.family_sizes) run(fams, n);
  for (auto n : o.mesh_sizes) run(rest, n);
  return all;
}

// Stage 2: the first failure at the smallest size of each (peer, source), shrunk and
// saved while the stage's time lasts (after it: saved unshrunk, "time").
std::map<std::pair<std::string, std::string>, Tally> shrink_and_tally(std::vector<VoronoiCase>& all,
                                                                      const VoronoiBoardOptions& o) {
  std::map<std::pair<std::string, std::string>, Tally> t;
  for (VoronoiCase& c : all) {
    Tally& k = t[{c.peer, c.source}];
    if (!c.not_judged.empty()) {
      ++k.not_judged;
      continue;
    }
    ++k.cases;
    ++k.verdicts[voronoi_verdict_name(c.run.verdict)];
    if (!c.failed()) continue;
    ++k.failing;
    if (!k.shrunk || c.n < k.shrunk->n) k.shrunk = &c;
  }
  const auto t0 = Clock::now();
  for (auto& [key, k] : t) {
    if (!k.shrunk) continue;
    VoronoiCase& c = *k.shrunk;
    const PointSource* src = nullptr;
    for (const auto& s : o.sources)
      if (s.name == c.source) src = &s;
    const bool in_time = seconds_since(t0) < o.shrink_seconds;
    VoronoiPeerOptions po;
    po.timeout_s = o.timeout_s;
    shrink_and_save_voronoi(c, src->generate(c.n, c.seed), po, in_time ? o.shrink_runs : 0, o.out_dir + "/voronoi",
                            "dtlab experiment leaderboard --seed " + std::to_string(o.seed) + " (Voronoi, " + c.source +
                                ", n " + std::to_string(c.n) + ", case " + std::to_string(c.index) + ")");
    if (!in_time) c.shrink_stop = "time";
  }
  return t;
}

// The exact relation of the points, built once for the checks of every peer; null
// (each check then builds and refuses on its own) for points it refuses.
std::shared_ptr<const VoronoiNeighbors> shared_relation(const std::vector<Point3>& points) {
  try {
    return voronoi_relation(points);
  } catch (const std::exception&) {
    return nullptr;
  }
}

// Stage 3: one run per peer and (speed source, size); the check's own time recorded,
// the shared relation's build (DT and tables) counted in every peer's check time.
std::vector<SpeedRow> run_speed(const VoronoiBoardOptions& o) {
  std::vector<SpeedRow> rows;
  VoronoiPeerOptions po;
  po.timeout_s = 600;
  for (const auto& src : o.speed_sources)
    for (auto n : o.speed_sizes) {
      const std::vector<Point3> points = src.generate(n, o.seed);
      const auto t = Clock::now();
      po.check.relation = shared_relation(points);
      const double relation_s = seconds_since(t);
      const double dt_s = po.check.relation ? po.check.relation->seconds_dt : 0;
      for (const auto& p : o.peers) {
        VoronoiPeerRun r = run_voronoi_peer(p, points, default_box(points, 0.1), po);
        if (r.report) r.report->witnesses.clear();
        rows.push_back({src.name, points.size(), std::move(r), po.check.relation ? relation_s : 0, dt_s});
      }
    }
  return rows;
}

// A number as the other data files print it (ostream's default: 6 significant digits).
template <class T>
std::string field(T v) {
  std::ostringstream f;
  f << v;
  return f.str();
}

// The tolerances the ulp floor decided ("vertex convex volume"; "" when none did).
std::string ulp_rules(const VoronoiTolerances& t) {
  std::string s;
  for (const auto& [name, a] : {std::pair{"vertex", t.vertex}, std::pair{"convex", t.convex},
                                std::pair{"small_face", t.small_face}, std::pair{"volume", t.volume}})
    if (a.ulps) s += (s.empty() ? "" : " ") + std::string(name);
  return s;
}

void write_csvs(const std::vector<VoronoiCase>& all, const std::vector<SpeedRow>& speed, const std::string& dir) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& c : all) {
    const auto* r = c.run.report ? &*c.run.report : nullptr;
    std::vector<std::string> row = {c.peer,
                                    c.source,
                                    field(c.n),
                                    field(c.index),
                                    field(c.seed),
                                    voronoi_verdict_name(c.run.verdict),
                                    c.not_judged.empty() ? "0" : "1",
                                    r ? voronoi_counts_text(*r) : "",
                                    field(r ? r->largest_wrong_face : 0),
                                    field(r ? r->largest_small_face : 0),
                                    field(r ? r->max_vertex_ulps : 0),
                                    r ? ulp_rules(r->tolerances) : "",
                                    field(c.run.seconds),
                                    field(c.run.wall_seconds),
                                    field(r ? r->seconds : 0)};
    if (c.corpus_file.empty()) {
      row.insert(row.end(), {"", "", "", ""});
    } else {
      row.insert(row.end(), {field(c.shrunk_points), c.shrunk_minimal ? "1" : "0",
                             voronoi_verdict_name(c.shrunk_verdict), c.corpus_file});
    }
    rows.push_back(std::move(row));
  }
  write_csv(dir + "/data/voronoi.csv",
            {"peer", "source", "n", "case", "seed", "verdict", "not_judged", "defects", "largest_wrong_face",
             "largest_small_face", "max_vertex_ulps", "ulp_tolerances", "seconds", "wall_seconds", "check_seconds", "shrunk_points", "minimal",
             "shrunk_verdict_fresh", "corpus_file"},
            rows);
  std::vector<std::vector<std::string>> speed_rows;
  for (const auto& sr : speed)
    speed_rows.push_back({sr.run.name, sr.source, field(sr.n), voronoi_verdict_name(sr.run.verdict),
                          field(sr.run.seconds), field(sr.run.wall_seconds), field(sr.check_s()),
                          field(sr.run.report ? sr.run.report->seconds_dt + sr.relation_dt_s : 0),
                          field(sr.run.peak_rss_bytes)});
  write_csv(dir + "/data/voronoi_speed.csv",
            {"peer", "source", "n", "verdict", "seconds", "wall_seconds", "check_seconds", "check_dt_seconds",
             "peak_rss_bytes"},
            speed_rows);
}

std::string verdicts_text(const std::map<std::string, std::size_t>& v) {
  std::string s;
  for (const auto& [name, k] : v) s += (s.empty() ? "" : ", ") + name + " " + std::to_string(k);
  return s.empty() ? "-" : s;
}

// Stage 4: the Markdown section.
std::string section(const VoronoiBoardOptions& o, const std::map<std::pair<std::string, std::string>, Tally>& t,
                    const std::vector<SpeedRow>& speed) {
  std::ostringstream m;
  m << "## Voronoi cells: which Voronoi code can you trust?\n\n"
       "Every Voronoi peer in its own process (time limit "
    << fmt("%g", o.timeout_s)
    << " s) on the same sources, sizes and seeds as above, its cells clipped to the points' bounding box grown by "
       "0.1 per side (as `dtlab voronoi`) and judged by the exact Voronoi checker (voronoi_check/README.md). A "
       "failure is any verdict but `exact-topology` and `rounded-topology` (only faces below 1e-9 of the extent "
       "squared wrong); coplanar inputs and boxes that overflow are not judged.\n\n";
  m << table_row({"peer", "version", "cases", "failing", "share [Wilson 95%]", "verdicts", "not judged"})
    << table_rule(7, 2);
  for (const auto& p : o.peers) {
    Tally sum;
    for (const auto& [key, k] : t)
      if (key.first == p) {
        sum.cases += k.cases, sum.failing += k.failing, sum.not_judged += k.not_judged;
        for (const auto& [v, n] : k.verdicts) sum.verdicts[v] += n;
      }
    const auto [lo, hi] = wilson_interval(sum.failing, sum.cases);
    m << table_row(
        {"`" + p + "`", voronoi_peer_version(p), std::to_string(sum.cases), std::to_string(sum.failing),
         percent(sum.cases ? double(sum.failing) / sum.cases : 0) + " [" + percent(lo) + ", " + percent(hi) + "]",
         verdicts_text(sum.verdicts), std::to_string(sum.not_judged)});
  }
  m << "\n### Per (peer, source)\n\n";
  m << table_row({"peer", "source", "failing/cases [Wilson 95%]", "verdicts", "saved input (points, minimal, fresh)"})
    << table_rule(5, 2);
  for (const auto& [key, k] : t) {
    if (!k.cases) continue;
    const auto [lo, hi] = wilson_interval(k.failing, k.cases);
    std::string saved = "-";
    if (k.shrunk && !k.shrunk->corpus_file.empty())
      saved = "`voronoi/" + k.shrunk->corpus_file + "` (" + std::to_string(k.shrunk->n) + " to " +
              std::to_string(k.shrunk->shrunk_points) + ", " +
              (k.shrunk->shrunk_minimal ? "1-minimal" : "not minimal: " + k.shrunk->shrink_stop) + ", " +
              voronoi_verdict_name(k.shrunk->shrunk_verdict) + ")";
    m << table_row(
        {"`" + key.first + "`", key.second,
         std::to_string(k.failing) + "/" + std::to_string(k.cases) + " [" + percent(lo) + "-" + percent(hi) + "]",
         verdicts_text(k.verdicts), saved});
  }
  m << "\nShrunk inputs replay with `dtlab voronoi voronoi/corpus/FILE.node --against PEER` (the command, "
       "relative to voronoi/, is in each sidecar .json); each was shrunk by delta debugging with every try in a fresh "
       "process, at most "
    << o.shrink_runs << " runs per pair, " << fmt("%.0f", o.shrink_seconds) << " s for the stage.\n\n";
  m << "### Voronoi speed\n\nSeconds: the cells as the peer times them; check: the exact checker on its cells "
       "(its DT and tables included: built once per source and size and counted in every peer's check), one thread; "
       "x dtlab: the check over `dtlab:adaptive`'s cells in the same run.\n\n";
  m << table_row({"source", "n", "peer", "verdict", "cells s", "process s", "check s", "check / dtlab:adaptive cells"})
    << table_rule(8, 4);
  for (const auto& s : speed) {
    double ours = 0;
    for (const auto& u : speed)
      if (u.source == s.source && u.n == s.n && u.run.name == "dtlab:adaptive" && u.run.report) ours = u.run.seconds;
    const bool answered = s.run.report.has_value();
    m << table_row({s.source, std::to_string(s.n), "`" + s.run.name + "`", voronoi_verdict_name(s.run.verdict),
                    answered ? fmt("%.3f", s.run.seconds) : "-", fmt("%.2f", s.run.wall_seconds),
                    answered ? fmt("%.2f", s.check_s()) : "-",
                    answered && ours > 0 ? fmt("%.2f", s.check_s() / ours) : "-"});
  }
  return m.str();
}

}  // namespace

VoronoiBoard run_voronoi_board(const VoronoiBoardOptions& o) {
  const auto t0 = Clock::now();
  std::vector<VoronoiCase> all = run_cases(o);
  const double runs_s = seconds_since(t0);
  const auto t1 = Clock::now();
  const auto tally = shrink_and_tally(all, o);
  const double shrink_s = seconds_since(t1);
  const auto t2 = Clock::now();
  const std::vector<SpeedRow> speed = run_speed(o);
  const double speed_s = seconds_since(t2);
  write_csvs(all, speed, o.out_dir);
  VoronoiBoard b;
  b.markdown = section(o, tally, speed);
  std::size_t failing = 0, saved = 0, minimal = 0;
  for (const auto& [key, k] : tally) {
    failing += k.failing > 0;
    saved += k.shrunk && !k.shrunk->corpus_file.empty();
    minimal += k.shrunk && k.shrunk->shrunk_minimal;
  }
  b.facts = {{"cases", all.size()},      {"failing_pairs", failing}, {"saved_pairs", saved},
             {"minimal_pairs", minimal}, {"runs_seconds", runs_s},   {"shrink_seconds", shrink_s},
             {"speed_seconds", speed_s}};
  return b;
}

}  // namespace dtlab::experiments
