// Orchestration and report of `dtlab experiment benchmark`.
#include "experiments/benchmark.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#include <malloc.h>
#include <sstream>

#include "kernel/output_file.hpp"
#include "bench/whole_run.hpp"
#include "experiments/point_sources.hpp"
#include "experiments/predicate_cost.hpp"
#include "experiments/report.hpp"
#include "experiments/thesis_parts.hpp"

namespace dtlab::experiments {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Plan {
  std::string distribution;
  std::vector<std::size_t> sizes;
};

std::vector<Plan> make_plan(const BenchmarkOptions& o) {
  const std::size_t cap = o.max_n ? o.max_n : o.quick ? 10000 : (o.large ? 10000000 : 1000000);
  const std::size_t other = o.large ? 1000000 : 100000;
  std::vector<Plan> plan = {{"uniform", {}}, {"clustered", {}}, {"lattice", {}}, {"torus-winding", {}}};
  for (auto& p : plan)
    for (std::size_t n = 1000; n <= std::min(cap, p.distribution == "uniform" ? cap : other); n *= 10)
      p.sizes.push_back(n);
  return plan;
}


std::string summary_markdown(const json& rows) {
  std::ostringstream o;
  o << table_row({"distribution", "n", "tool", "runs", "median s", "min s", "max s", "spread", "Mpoints/s",
                  "peak MB", "own MB", "tets", "bytes/tet"})
    << table_rule(13, 3);
  for (const auto& r : rows) {
    if (!r["ok"].get<bool>()) {
      o << table_row({r["distribution"], r["n"].dump(), r["tool"], r["runs"].dump(),
                      "no answer: " + r["note"].get<std::string>(), "", "", "", "", "", "", "", ""});
      continue;
    }
    o << table_row({r["distribution"], r["n"].dump(), r["tool"], r["runs"].dump(), fmt("%.4f", r["median_s"]),
                    fmt("%.4f", r["min_s"]), fmt("%.4f", r["max_s"]), fmt("%.0f%%", 100 * r["spread"].get<double>()),
                    fmt("%.3f", r["mpoints_per_s"]), fmt("%.0f", r["peak_mb"]), fmt("%.0f", r["own_mb"]), r["tets"].dump(),
                    r["tool"] == "dtlab" ? fmt("%.0f", r["bytes_per_tet"]) : ""});
  }
  o << "\n";
  return o.str();
}

std::string speedup_markdown(const json& rows) {
  std::ostringstream o;
  std::map<std::pair<std::string, std::size_t>, std::map<std::string, double>> t;
  for (const auto& r : rows)
    if (r["ok"].get<bool>()) t[{r["distribution"], r["n"]}][r["tool"]] = r["median_s"];
  o << table_row({"distribution", "n", "dtlab s", "CGAL s", "TetGen s", "dtlab / CGAL", "dtlab / TetGen"})
    << table_rule(7, 1);
  for (const auto& [key, m] : t) {
    auto get = [&](const char* k) { auto it = m.find(k); return it == m.end() ? 0.0 : it->second; };
    const double d = get("dtlab"), c = get("cgal"), g = get("tetgen");
    o << table_row({key.first, std::to_string(key.second), d ? fmt("%.4f", d) : "-", c ? fmt("%.4f", c) : "-",
                    g ? fmt("%.4f", g) : "-", d && c ? fmt("%.2f", d / c) : "-", d && g ? fmt("%.2f", d / g) : "-"});
  }
  o << "\n";
  return o.str();
}

Timing timing_of(const json& r) {
  return {r["median_s"].get<double>(), r["min_s"].get<double>(), r["max_s"].get<double>(), r["runs"].get<int>()};
}

double stage_share(const json& row, const char* stage) {
  const double calls = row["calls"].get<double>();
  return row["stages"].contains(stage) && calls > 0 ? row["stages"][stage].get<double>() / calls : 0.0;
}

// Every sentence carries its number: timing claims from repeated runs, filter shares
// from the stage counts of the same report.
std::string findings_markdown(const json& rows, const json& pred) {
  std::ostringstream o;
  std::map<std::string, std::map<std::size_t, std::map<std::string, json>>> by;
  for (const auto& r : rows)
    if (r["ok"].get<bool>()) by[r["distribution"]][r["n"].get<std::size_t>()][r["tool"]] = r;
  for (const auto& [dist, sizes] : by) {
    // the largest n with repeated runs of all three tools
    const std::map<std::string, json>* cell = nullptr;
    std::size_t n = 0;
    for (const auto& [size, tools] : sizes)
      if (tools.size() == 3 && tools.at("dtlab")["runs"].get<int>() > 1) cell = &tools, n = size;
    if (!cell) continue;
    const json &d = cell->at("dtlab"), &c = cell->at("cgal"), &g = cell->at("tetgen");
    o << "- `" << dist << "`, n = " << n << ": dtlab vs CGAL " << timing_claim(timing_of(d), timing_of(c))
      << "; dtlab vs TetGen " << timing_claim(timing_of(d), timing_of(g)) << ". Peak memory above the fork "
      << "baseline: dtlab " << fmt("%.0f", d["own_mb"]) << " MB, CGAL " << fmt("%.0f", c["own_mb"]) << " MB, TetGen "
      << fmt("%.0f", g["own_mb"]) << " MB (TetGen: its whole process).\n";
  }
  std::map<std::string, std::map<std::string, json>> adaptive;
  for (const auto& r : pred)
    if (r["backend"] == "adaptive") adaptive[r["points"]][r["predicate"]] = r;
  if (adaptive.count("uniform") && adaptive.count("near_degenerate")) {
    const auto& u = adaptive["uniform"];
    const auto& h = adaptive["near_degenerate"];
    o << "- The semi-static filter of `adaptive` decided " << fmt("%.3g%%", 100 * stage_share(u.at("orient3d"), "semistatic"))
      << " of orient3d and " << fmt("%.3g%%", 100 * stage_share(u.at("insphere"), "semistatic"))
      << " of insphere calls on `uniform` tuples, and " << fmt("%.3g%%", 100 * stage_share(h.at("orient3d"), "semistatic"))
      << " and " << fmt("%.3g%%", 100 * stage_share(h.at("insphere"), "semistatic"))
      << " on `near_degenerate` tuples, where the rest went to the later stages (table below). Cost per call "
         "(best of 3 passes): orient3d " << fmt("%.1f", u.at("orient3d")["ns_per_call"]) << " ns on uniform vs "
      << fmt("%.1f", h.at("orient3d")["ns_per_call"]) << " ns on near_degenerate, insphere "
      << fmt("%.1f", u.at("insphere")["ns_per_call"]) << " vs " << fmt("%.1f", h.at("insphere")["ns_per_call"]) << " ns.\n";
  }
  o << "\n";
  return o.str();
}

std::string predicates_markdown(const json& pred) {
  std::ostringstream o;
  o << table_row({"points", "backend", "predicate", "calls", "ns/call", "zero answers", "adaptive stages"})
    << table_rule(7, 3);
  for (const auto& r : pred) {
    std::string st;
    for (const auto& [k, v] : r["stages"].items())
      st += (st.empty() ? "" : ", ") + k + " " + fmt("%.3g%%", 100.0 * v.get<double>() / r["calls"].get<double>());
    o << table_row({r["points"], r["backend"], r["predicate"], r["calls"].dump(), fmt("%.1f", r["ns_per_call"]),
                    r["zeros"].dump(), st});
  }
  o << "\n";
  return o.str();
}

std::string stages_markdown(const json& builds) {
  std::ostringstream o;
  o << table_row({"distribution", "n", "backend", "build s", "build failure", "orient3d calls", "insphere calls",
                  "stages (share of calls)"})
    << table_rule(8, 3);
  for (const auto& b : builds) {
    std::uint64_t o3 = 0, is = 0;
    for (const auto& [k, v] : b["stages"].items()) (k.rfind("orient3d", 0) == 0 ? o3 : is) += v.get<std::uint64_t>();
    std::string st;
    for (const auto& [k, v] : b["stages"].items())
      st += (st.empty() ? "" : ", ") + k + " " +
            fmt("%.3g%%", 100.0 * v.get<double>() / double(k.rfind("orient3d", 0) == 0 ? o3 : is));
    const std::string failure = b["failure"];
    o << table_row({b["distribution"], b["n"].dump(), b["backend"], fmt("%.3f", b["seconds"]),
                    failure.empty() ? "-" : failure, b["orient3d_calls"].dump(), b["insphere_calls"].dump(), st.empty() ? "-" : st});
  }
  o << "\n";
  return o.str();
}

// Everything the benchmark measured, for data/ and the report.
struct BenchmarkData {
  json rows = json::array(), runs_json = json::array(), builds = json::array();
  std::vector<std::vector<std::string>> run_rows, sum_rows;
  bool dtlab_failed = false;
};

// `runs` whole runs of one tool on `points` (each in its forked child), and its row.
void measure_tool(const std::string& distribution, std::vector<Point3>& points, const std::string& tool, int runs,
                  double baseline_mb, const PredicateSpec& spec, const BuildOptions& bo, BenchmarkData& data) {
  BenchRow row{distribution, points.size(), tool, {}};
  for (int r = 0; r < runs; ++r) {
    row.runs.push_back(measure_run(tool, points, spec, bo));
    const RunMeasure& m = row.runs.back();
    data.runs_json.push_back({{"distribution", distribution},
                              {"n", points.size()},
                              {"tool", tool},
                              {"run", r},
                              {"ok", m.ok},
                              {"seconds", m.seconds},
                              {"peak_mb", m.peak_mb},
                              {"tets", m.tets},
                              {"note", m.note}});
    data.run_rows.push_back({distribution, std::to_string(points.size()), tool, std::to_string(r), m.ok ? "1" : "0",
                             fmt("%.6f", m.seconds), fmt("%.1f", m.peak_mb), std::to_string(m.tets), m.note});
  }
  const RunMeasure& last = row.runs.back();
  const bool ok = row.median_seconds() > 0;
  if (tool == "dtlab" && !ok) data.dtlab_failed = true;
  const double med = row.median_seconds();
  json j = {{"distribution", distribution},
            {"n", points.size()},
            {"tool", tool},
            {"runs", runs},
            {"ok", ok},
            {"median_s", med},
            {"min_s", row.min_seconds()},
            {"max_s", row.max_seconds()},
            {"spread", med > 0 ? (row.max_seconds() - row.min_seconds()) / med : 0.0},
            {"mpoints_per_s", med > 0 ? double(points.size()) / med / 1e6 : 0.0},
            {"peak_mb", row.median_peak_mb()},
            {"baseline_mb", tool == "tetgen" ? 0.0 : baseline_mb},
            {"own_mb", std::max(0.0, row.median_peak_mb() - (tool == "tetgen" ? 0.0 : baseline_mb))},
            {"tets", last.tets},
            {"bytes_per_tet", last.bytes_per_tet},
            {"note", last.note}};
  data.rows.push_back(j);
  data.sum_rows.push_back({distribution, std::to_string(points.size()), tool, std::to_string(runs), ok ? "1" : "0",
                           fmt("%.6f", med), fmt("%.6f", row.min_seconds()), fmt("%.6f", row.max_seconds()),
                           fmt("%.4f", j["mpoints_per_s"]), fmt("%.1f", j["peak_mb"]), fmt("%.1f", j["baseline_mb"]),
                           fmt("%.1f", j["own_mb"]), std::to_string(last.tets), fmt("%.1f", last.bytes_per_tet),
                           last.note});
}

// Predicate calls and adaptive stages of dtlab's in-process builds with naive,
// adaptive and (up to 10^5) exact predicates.
void measure_builds(const std::string& distribution, const std::vector<Point3>& points, std::size_t n,
                    const PredicateSpec& spec, const BuildOptions& bo, BenchmarkData& data) {
  for (const std::string backend : {"naive", "adaptive", "exact"}) {
    if (backend == "exact" && n > 100000) continue;
    PredicateSpec s = spec;
    s.backend = backend;
    s.perturb = backend != "naive";
    const auto b0 = std::chrono::steady_clock::now();
    const BuildResult r = build_delaunay(points, s, bo);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - b0).count();
    json stages = json::object();
    for (const auto& [name, calls] : r.stats.stages) stages[name] = calls;
    data.builds.push_back({{"distribution", distribution},
                           {"n", points.size()},
                           {"backend", backend + (s.perturb ? "+sos" : "")},
                           {"seconds", sec},
                           {"failure", r.failure ? failure_name(r.failure->kind) : ""},
                           {"orient3d_calls", r.stats.orient3d_calls},
                           {"insphere_calls", r.stats.insphere_calls},
                           {"walk_steps", r.stats.walk_steps},
                           {"stages", stages}});
  }
}

// report.md's text.
std::string benchmark_markdown(const fs::path& dir, const BenchmarkOptions& options, const BenchmarkData& data,
                               const json& pred, const json& env) {
  std::ostringstream o;
  o << "# dtlab benchmark: dtlab vs CGAL vs TetGen\n\n";
  o << "Whole Delaunay tetrahedralizations of the same points by dtlab (adaptive predicates + symbolic "
       "perturbation, infinite vertex, BRIO/Hilbert order), CGAL (`Delaunay_triangulation_3`, exact predicates, "
       "range insertion with spatial sort) and TetGen (`tetgen -QzJNF`: its own process, reading and writing "
       "files). Each run happens in a forked child (`bench/whole_run.hpp`) so that its peak resident memory is "
       "its own; for dtlab and CGAL the time is the triangulation call, for TetGen the whole process. Runs per "
       "point: " << options.runs << " for n <= 10^5, 1 above (median, min, max; spread = (max - min) / median). "
       "Peak MB is the child's peak resident memory; for dtlab and CGAL it includes the input points and the "
       "parent's pages inherited by the fork, so `own MB` subtracts the peak of the same child doing nothing "
       "(`baseline_mb` in `data/summary.csv`). TetGen runs as its own process: its peak is its own.\n\n";
  o << "Distributions: `uniform` (unit cube), `clustered` (1-6 clusters of radius 2^-4..2^-40), `lattice` "
       "(a full integer grid: massively cospherical), `torus-winding` (points sampled inside the bumpy torus "
       "by the winding-number sampler). Single thread for every tool.";
  if (options.quick)
    o << " **Quick run** (`--quick`): n up to " << (options.max_n ? options.max_n : 10000)
      << " and fewer predicate calls; the full run goes to 10^6.";
  o << "\n\n## Findings\n\nTimes are medians with [min, max] of the runs; a difference smaller than the spread "
       "of the runs is reported as no measurable difference.\n\n"
    << findings_markdown(data.rows, pred);
  o << "## Times and memory\n\n" << summary_markdown(data.rows);
  o << "## Ratios (median times)\n\n" << speedup_markdown(data.rows);
  o << figure_markdown(dir, "fig_time.png", "Time vs n (log-log): median, bars from the fastest to the slowest run");
  o << figure_markdown(dir, "fig_rate.png", "Million points per second vs n: median, bars from the slowest to the fastest run");
  o << figure_markdown(dir, "fig_memory.png", "Peak memory above the fork baseline vs n (median of the runs)");
  o << "## Predicate cost per backend\n\n"
       "`uniform`: random tuples from 4096 uniform points (general position). `near_degenerate`: each "
       "orient3d tuple has its 4th point computed (and rounded) on the plane of the first three, each insphere "
       "tuple has 5 points rounded from one sphere, so the exact determinant is within the rounding error and "
       "a float filter cannot decide it. `adaptive stages`: the share of calls each stage decided (`semistatic` "
       "the filter, A..D Shewchuk's stages, `exact` the fallback), counted in a second, untimed pass.\n\n"
    << predicates_markdown(pred);
  o << figure_markdown(dir, "fig_predicates.png", "Nanoseconds per predicate call (best of 3 passes), uniform and near-degenerate tuples");
  o << "## Predicate calls and adaptive stages inside dtlab builds\n\n"
       "In-process builds of the same points with naive (no perturbation), adaptive+sos and exact+sos "
       "(exact only up to 10^5). A naive build that stops (`walk-cycle`) is fast because it did not finish.\n\n"
    << stages_markdown(data.builds);
  o << "## Data\n\n`data/runs.csv` (every run), `data/summary.csv` (medians), `data/results.json` (all, with "
       "the predicate and stage tables); `plot_figures.py` drew the figures (`/usr/bin/python3 plot_figures.py .`).\n\n";
  o << environment_markdown(env);
  return o.str();
}

}  // namespace

ExperimentResult run_benchmark(const BenchmarkOptions& options) {
  const fs::path dir = options.out;
  fs::create_directories(dir / "data");
  const auto t0 = std::chrono::steady_clock::now();
  auto step = [&](const std::string& what) {
    if (options.progress)
      std::fprintf(stderr, "[%6.1f s] %s\n",
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), what.c_str());
  };
  const PredicateSpec spec;  // adaptive + SoS, the default
  const std::vector<std::string> tools = {"dtlab", "cgal", "tetgen"};
  BenchmarkData data;
  for (const Plan& p : make_plan(options))
    for (std::size_t n : p.sizes) {
      const std::uint64_t seed = case_seed(options.seed, "benchmark/" + p.distribution, n, 0);
      step(p.distribution + " n=" + std::to_string(n));
      std::vector<Point3> points = experiment_points(p.distribution, n, seed);
      BuildOptions bo;
      bo.seed = seed;
      // the forked child's resident memory before it does anything: the baseline (the
      // points and the parent's heap; freed blocks are handed back to the system first)
      malloc_trim(0);
      const double baseline_mb = measure_run("none", points, spec, bo).peak_mb;
      const int runs = n <= 100000 ? options.runs : 1;
      for (const auto& tool : tools) measure_tool(p.distribution, points, tool, runs, baseline_mb, spec, bo, data);
      // predicate calls and adaptive stages of dtlab's build at 10^5 (or the largest below)
      if (n == std::min<std::size_t>(100000, p.sizes.back())) measure_builds(p.distribution, points, n, spec, bo, data);
    }
  step("predicate costs");
  const json pred = measure_predicate_costs(
      options.quick || (options.max_n && options.max_n < 100000) ? 200000 : 2000000, options.seed);

  write_csv(dir / "data" / "runs.csv", {"distribution", "n", "tool", "run", "ok", "seconds", "peak_mb", "tets", "note"},
            data.run_rows);
  write_csv(dir / "data" / "summary.csv",
            {"distribution", "n", "tool", "runs", "ok", "median_s", "min_s", "max_s", "mpoints_per_s", "peak_mb",
             "baseline_mb", "own_mb", "tets", "bytes_per_tet", "note"},
            data.sum_rows);
  const json env = environment(options.command_line, options.seed);
  write_text_file((dir / "data" / "results.json").string(), json{{"experiment", "benchmark"},
                                                                 {"environment", env},
                                                                 {"summary", data.rows},
                                                                 {"runs", data.runs_json},
                                                                 {"builds", data.builds},
                                                                 {"predicates", pred}}
                                                                    .dump(1) +
                                                                "\n");
  write_text_file((dir / "environment.json").string(), env.dump(2) + "\n");
  write_text(dir / "commands.sh", "#!/bin/sh\n# the command that wrote this report\n" + options.command_line +
                                      "\n# redraw the figures from data/\n/usr/bin/python3 plot_figures.py .\n");
  json facts = {{"rows", data.rows.size()}, {"dtlab_failed", data.dtlab_failed}};
  if (options.figures) {
    step("figures");
    facts["figures_status"] = draw_figures(dir);
  }
  const std::string report = benchmark_markdown(dir, options, data, pred, env);
  write_text(dir / "report.md", report);
  write_text(dir / "report.html", markdown_to_html(report, "dtlab benchmark"));
  facts["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_text_file((dir / "data" / "facts.json").string(), facts.dump(2) + "\n");
  step("done");
  return {data.dtlab_failed ? 1 : 0, facts};
}

}  // namespace dtlab::experiments
