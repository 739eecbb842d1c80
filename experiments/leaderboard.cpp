#include "experiments/leaderboard.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include "experiments/csv_writer.hpp"
#include "experiments/leaderboard_voronoi.hpp"
#include "experiments/peer_campaign.hpp"
#include "experiments/report.hpp"
#include "experiments/shrink_stage.hpp"
#include "experiments/thesis_parts.hpp"
#include "experiments/wilson_interval.hpp"
#include "fuzz/campaign.hpp"
#include "fuzz/families.hpp"
#include "fuzz/work_queue.hpp"
#include "kernel/input_error.hpp"
#include "kernel/output_file.hpp"
#include "oracle/peers/child_process.hpp"
#include "oracle/peers/peer_json.hpp"
#include "oracle/peers/served_child.hpp"
#include "oracle/peers/temp_dir.hpp"
#include "sampling/mesh_io.hpp"
#include "sampling/mesh_sampler.hpp"
#include "voronoi_check/voronoi_peers.hpp"

namespace dtlab::experiments {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr const char* kDefaultCgalData = "/usr/share/doc/libcgal-demo/data.tar.gz";

// The files a run writes besides its corpora, the last one written first.
constexpr const char* kRunFiles[] = {"data/facts.json", "report.md",      "report.html",      "environment.json",
                                     "leaderboard.csv", "data/speed.csv", "data/voronoi.csv", "data/voronoi_speed.csv"};
// CGAL demo meshes sampled on the surface (the points of a scanned shell) and inside.
const std::vector<std::string> kMeshes = {"elephant", "bunny00", "fandisk", "knot1"};

struct MeshSet {
  std::vector<TriangleMesh> meshes;
  std::vector<std::string> names;
  std::string note;  // why there are none
};

MeshSet load_meshes(const std::string& archive, const std::vector<std::string>& wanted) {
  MeshSet set;
  if (!fs::exists(archive)) {
    set.note = archive + " not found (Debian package libcgal-demo)";
    return set;
  }
  TempDir dir("dtlab-meshes");
  std::vector<std::string> args = {"tar", "xzf", archive, "-C", dir.path().string()};
  for (const auto& m : wanted) args.push_back("data/meshes/" + m + ".off");
  const ChildResult r = run_child(args, ChildLimits::of(120, dir.file("tar.log")));
  if (r.status != ChildStatus::exited) set.note = "tar failed on " + archive;
  for (const auto& m : wanted) {
    const fs::path off = dir.path() / "data" / "meshes" / (m + ".off");
    if (!fs::exists(off)) continue;
    try {
      set.meshes.push_back(read_mesh(off.string()));
      set.names.push_back(m);
    } catch (const std::exception& e) {
      set.note += std::string(" ") + m + ": " + e.what();
    }
  }
  return set;
}

std::string counts_field(const PeerRun& r) {
  std::string s;
  if (r.report)
    for (int k = 0; k < kDefectKinds; ++k)
      if (r.report->counts[k])
        s += (s.empty() ? "" : ";") + std::string(defect_name(static_cast<DefectKind>(k))) + ":" +
             std::to_string(r.report->counts[k]);
  if (r.extra_tets) s += (s.empty() ? "" : ";") + std::string("extra-tets:") + std::to_string(r.extra_tets);
  return s;
}

std::string percent(double v) {
  char b[16];
  std::snprintf(b, sizeof b, "%.0f%%", 100 * v);
  return b;
}

// Heat colour from white (0) to red (1).
std::string heat_colour(double share) {
  const int g = static_cast<int>(255 - 200 * std::clamp(share, 0.0, 1.0));
  char b[16];
  std::snprintf(b, sizeof b, "#ff%02x%02x", g, g);
  return share == 0 ? "#e8f5e9" : b;
}

// How a pair's shrink ended: 1-minimal, or what stopped it.
std::string shrink_ending(const PeerCase& c) { return c.shrunk_minimal ? "1-minimal" : c.shrink_stop; }

struct Cell {
  std::size_t cases = 0, failing = 0;
  std::map<std::string, std::size_t> verdicts;  // non-delaunay verdicts
  const PeerCase* smallest = nullptr;           // smallest shrunk failing input
};

struct SpeedRow {
  std::string source;
  std::size_t n;
  PeerRun run;
};

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// One leaderboard run: its settings, its sources and what each stage leaves for the
// next. Each stage is a member function with its contract above it.
class Leaderboard {
 public:
  explicit Leaderboard(const LeaderboardOptions& o) : options(o), dir(o.out), t0(std::chrono::steady_clock::now()) {}

  ExperimentResult run() {
    plan();
    load_sources();
    run_robustness();
    shrink_failures();
    run_speed();
    write_csvs();
    tabulate();
    write_environment();
    const std::string voronoi = voronoi_section();
    std::ostringstream o;
    summary_section(o);
    shrink_section(o);
    speed_section(o);
    o << voronoi;
    data_section(o);
    write_reports(o.str());
    ExperimentResult r = write_facts();
    step("done");
    return r;
  }

 private:
  void step(const std::string& what) const {
    if (options.progress) std::fprintf(stderr, "  [%6.1f s] %s\n", seconds_since(t0), what.c_str());
  }

  // An earlier run's files go before this run writes any (data/facts.json, the mark of a
  // whole run, first): at any interrupt the folder holds only this run's files, never a
  // report beside another run's data. The corpora go whole: a peer left out this time
  // keeps no failure there.
  void remove_earlier_run() const {
    refuse_a_campaign_folder();
    std::vector<std::string> files;
    for (const char* name : kRunFiles) files.push_back((dir / name).string());
    std::size_t removed = remove_output_set(files, {options.cgal_data}).size();
    const auto any = [](const CorpusName&, const std::string&) { return true; };
    removed += remove_corpus_names(dir.string(), any).size();
    removed += remove_corpus_names((dir / "voronoi").string(), any).size();
    if (removed) step("removed " + std::to_string(removed) + " files of an earlier run");
  }

  // A fuzz campaign's folder (its settings.json, results*.jsonl) names its corpus as the
  // leaderboard does: cleaning it as an earlier leaderboard run would remove the
  // campaign's failures. Refused (exit 2) before anything is removed.
  void refuse_a_campaign_folder() const {
    std::error_code ec;
    bool campaign = fs::exists(dir / "settings.json", ec);
    for (fs::directory_iterator it(dir, ec), end; !campaign && !ec && it != end; it.increment(ec))
      campaign = fuzz::is_results_file(it->path().filename().string());
    if (campaign)
      throw InputError(dir.string(), 0,
                       "holds a fuzz campaign (settings.json, results*.jsonl): the leaderboard would remove its "
                       "corpus; choose another --out");
  }

  // Settings from the options: peers, seeds, sizes, limits.
  void plan() {
    remove_earlier_run();
    fs::create_directories(dir / "data");
    if (options.peers != std::vector<std::string>{"none"}) peers = expand_peer_names(options.peers);
    cases = options.cases ? options.cases : options.quick ? 2 : 3;
    family_sizes = options.quick ? std::vector<std::size_t>{48} : std::vector<std::size_t>{48, 1000};
    mesh_sizes = options.quick ? std::vector<std::size_t>{3000} : std::vector<std::size_t>{3000, 10000};
    speed_sizes = options.quick ? std::vector<std::size_t>{10000} : std::vector<std::size_t>{100000, 1000000};
    if (options.speed_n) speed_sizes = {options.speed_n};
    po.timeout_s = options.timeout_s > 0 ? options.timeout_s : options.quick ? 10 : 30;
    shrink_runs = options.shrink_runs ? options.shrink_runs : options.quick ? 48 : 300;
    shrink_stage_s = options.shrink_seconds > 0 ? options.shrink_seconds : options.quick ? 30 : 600;
  }

  // Point sources: every fuzz family, then surface and volume samples of the meshes.
  void load_sources() {
    step("meshes");
    const std::vector<std::string> meshes_wanted =
        options.quick ? std::vector<std::string>{"elephant", "fandisk"} : kMeshes;
    meshes = options.meshes
                 ? load_meshes(options.cgal_data.empty() ? kDefaultCgalData : options.cgal_data, meshes_wanted)
                 : MeshSet{{}, {}, "left out (--no-meshes)"};
    for (const auto& m : meshes.meshes) samplers.push_back(std::make_unique<MeshSampler>(m));
    std::vector<std::string> family_names = options.families;
    if (family_names.empty())
      for (const auto& f : fuzz::families()) family_names.push_back(f.name);
    families = fuzz_family_sources(family_names);
    for (std::size_t i = 0; i < samplers.size(); ++i) {
      const MeshSampler* s = samplers[i].get();
      mesh_sources.push_back({meshes.names[i] + "-surface",
                              [s](std::size_t n, std::uint64_t seed) { return s->surface(n, seed).points; }});
      mesh_sources.push_back(
          {meshes.names[i] + "-volume", [s](std::size_t n, std::uint64_t seed) { return s->winding(n, seed).points; }});
    }
  }

  // Robustness: peers x sources x sizes x seeds; a peer not installed is run once.
  void run_robustness() {
    // Robustness: peers x sources x sizes x seeds.
    // A peer that is not installed is run once and reported as such.
    for (const std::string& peer : peers) {
      const PeerRun probe = run_peer(peer, families.front().generate(8, 1), po);
      if (probe.verdict != Verdict::not_installed) {
        runnable.push_back(peer);
        continue;
      }
      PeerCase c;
      c.peer = peer;
      c.source = "(any)";
      c.run = probe;
      all.push_back(c);
    }
    // Every peer's cases of one size in one work queue, so that a slow or hung run of
    // one peer overlaps with the others'.
    const auto runs_t0 = std::chrono::steady_clock::now();
    const auto run_sources = [&](const std::vector<PointSource>& sources, std::size_t n) {
      if (runnable.empty() || sources.empty()) return;
      step("runs at n = " + std::to_string(n) + " (" + std::to_string(sources.size()) + " sources)");
      PeerCampaignOptions o;
      o.peers = runnable;
      o.sources = sources;
      o.cases = cases;
      o.min_points = o.max_points = n;
      o.seed = options.seed;
      o.out_dir = "";  // shrinking below: one input per (peer, source)
      o.peer_options = po;
      o.jobs = options.jobs;
      auto got = run_peer_campaign(o);
      for (auto& c : got) all.push_back(std::move(c));
    };
    for (std::size_t n : family_sizes) run_sources(families, n);
    for (std::size_t n : mesh_sizes) run_sources(mesh_sources, n);
    stage_seconds["runs"] = seconds_since(runs_t0);
    // Rows in the order of the peers; the process seconds each peer's runs took.
    std::stable_sort(all.begin(), all.end(), [&](const PeerCase& a, const PeerCase& b) {
      return std::find(peers.begin(), peers.end(), a.peer) < std::find(peers.begin(), peers.end(), b.peer);
    });
    json& per_peer_seconds = stage_seconds["runs_process_seconds"] = json::object();
    for (const PeerCase& c : all) per_peer_seconds[c.peer] = per_peer_seconds.value(c.peer, 0.0) + c.run.wall_seconds;
  }

  // The first failure of each (peer, source), shrunk under the stage's budget.
  void shrink_failures() {
    // The smallest failing input per (peer, source): the first failure of the smallest
    // size (a hang only when the pair has no other failure), shrunk in passes under the
    // stage's time budget (experiments/shrink_stage.hpp).
    step("shrinking failures");
    const auto shrink_t0 = std::chrono::steady_clock::now();
    std::map<std::pair<std::string, std::string>, PeerCase*> first_failure;
    std::map<std::pair<std::string, std::string>, double> slowest_answer;  // non-hung runs, for a hang's tries
    for (PeerCase& c : all) {
      if (c.run.verdict != Verdict::hung) {
        double& t = slowest_answer[{c.peer, c.source}];
        t = std::max(t, c.run.wall_seconds);
      }
      if (c.failed()) {
        auto& slot = first_failure[{c.peer, c.source}];
        const auto rank = [](const PeerCase* p) { return std::make_pair(p->run.verdict == Verdict::hung, p->n); };
        if (!slot || rank(&c) < rank(slot)) slot = &c;
      }
    }
    for (auto& [key, c] : first_failure) {
      const PointSource* src = nullptr;
      for (const auto& s : families)
        if (s.name == c->source) src = &s;
      for (const auto& s : mesh_sources)
        if (s.name == c->source) src = &s;
      if (!src) continue;
      ShrinkPair p;
      p.failure = c;
      p.points = src->generate(c->n, c->seed);
      p.command = "dtlab experiment leaderboard --seed " + std::to_string(options.seed) + " (" + c->source + ", n " +
                  std::to_string(c->n) + ", case " + std::to_string(c->index) + ")";
      if (c->run.verdict == Verdict::hung) p.hung_try_seconds = hung_try_limit(slowest_answer[key], po.timeout_s);
      to_shrink.push_back(std::move(p));
    }
    ShrinkStageOptions stage;
    stage.seconds = shrink_stage_s;
    stage.runs_per_pass = shrink_runs;
    stage.jobs = options.jobs;
    stage.peer_options = po;
    stage.out_dir = dir.string();
    shrunk_stage = run_shrink_stage(to_shrink, stage);
    stage_seconds["shrinking"] = seconds_since(shrink_t0);
    stage_seconds["shrink_passes"] = shrunk_stage.pass_seconds;
    stage_seconds["shrink_pass_pairs"] = shrunk_stage.pass_pairs;
    stage_seconds["shrink_confirm"] = shrunk_stage.confirm_seconds;
    stage_seconds["shrink_reserved_for_confirming"] = shrunk_stage.reserved_seconds;
  }

  // Speed: one run per peer, uniform and mesh-sampled (ratio to CGAL in the report).
  void run_speed() {
    // Speed: ratio to CGAL in the same run, uniform and mesh-sampled.
    step("speed");
    const auto speed_t0 = std::chrono::steady_clock::now();
    std::vector<PointSource> speed_sources = fuzz_family_sources({"uniform"});
    if (!mesh_sources.empty()) speed_sources.push_back(mesh_sources[1]);  // the first mesh, volume samples
    PeerOptions speed_po = po;
    speed_po.timeout_s = options.quick ? 60 : 600;
    for (const auto& src : speed_sources)
      for (std::size_t n : speed_sizes) {
        const std::vector<Point3> points = src.generate(n, options.seed);
        for (const std::string& peer : peers) {
          step("speed " + src.name + " " + std::to_string(n) + " " + peer);
          PeerRun r = run_peer(peer, points, speed_po);
          r.mesh.reset();
          speed.push_back({src.name, points.size(), std::move(r)});
        }
      }

    stage_seconds["speed"] = seconds_since(speed_t0);
  }

  // leaderboard.csv and data/speed.csv.
  void write_csvs() const {
    // leaderboard.csv
    {
      std::ostringstream csv;
      csv << "peer,source,n,case,seed,lower_dimensional,verdict,defects,tets,seconds,wall_seconds,peak_rss_bytes,"
             "message,shrunk_points,shrink_ended,shrink_passes,shrink_runs,shrink_seconds,hung_try_seconds,"
             "shrunk_verdict_fresh,corpus_file\n";
      for (const PeerCase& c : all) {
        csv << c.peer << "," << c.source << "," << c.n << "," << c.index << "," << c.seed << ","
            << (c.lower_dimensional ? 1 : 0) << "," << verdict_name(c.run.verdict) << ","
            << csv_escape(counts_field(c.run)) << "," << (c.run.report ? c.run.report->stats.tets : 0) << ","
            << c.run.seconds << "," << c.run.wall_seconds << "," << c.run.peak_rss_bytes << ","
            << csv_escape(c.run.message) << ",";
        if (c.corpus_file.empty()) {
          csv << ",,,,,,,\n";
          continue;
        }
        csv << c.shrunk_points << "," << shrink_ending(c) << "," << c.shrink_passes << "," << c.shrink_runs << ","
            << c.shrink_seconds << "," << c.hung_try_seconds << "," << verdict_name(c.shrunk_verdict) << ","
            << c.corpus_file << "\n";
      }
      write_text_file((dir / "leaderboard.csv").string(), csv.str());
      std::ostringstream sp;
      sp << "peer,source,n,verdict,tets,seconds,wall_seconds,peak_rss_bytes\n";
      for (const auto& s : speed)
        sp << s.run.name << "," << s.source << "," << s.n << "," << verdict_name(s.run.verdict) << ","
           << (s.run.report ? s.run.report->stats.tets : 0) << "," << s.run.seconds << "," << s.run.wall_seconds << ","
           << s.run.peak_rss_bytes << "\n";
      write_text_file((dir / "data" / "speed.csv").string(), sp.str());
    }
  }

  // Cells of the heatmap, per-peer totals, whether a robust dtlab backend failed.
  void tabulate() {
    // Cells of the heatmap.
    for (const auto& s : families) sources.push_back(s.name);
    for (const auto& s : mesh_sources) sources.push_back(s.name);
    for (const PeerCase& c : all) {
      if (c.run.verdict == Verdict::not_installed) {
        not_installed[c.peer] = c.run.message;
        continue;
      }
      Cell& cell = cells[{c.peer, c.source}];
      Cell& total = per_peer[c.peer];
      ++cell.cases, ++total.cases;
      if (c.failed()) {
        ++cell.failing, ++total.failing;
        ++cell.verdicts[verdict_name(c.run.verdict)];
        ++total.verdicts[verdict_name(c.run.verdict)];
        if (c.peer == "dtlab:adaptive" || c.peer == "dtlab:exact") robust_failed = true;
      }
      if (!c.corpus_file.empty()) cell.smallest = &c;
    }
  }

  // environment.json with each peer's version.
  void write_environment() {
    env = environment(options.command_line, options.seed);
    versions = json::object();
    for (const auto& p : peers) versions[p] = peer_version(p, po);
    env["peers"] = versions;
    write_text_file((dir / "environment.json").string(), env.dump(2) + "\n");
  }

  // The report's head and its summary per peer.
  void summary_section(std::ostringstream& o) {
    o << "# Which Delaunay code can you trust? (dtlab leaderboard" << (options.quick ? ", quick run" : "") << ")\n\n";
    o << "Every peer ran in its own process (time limit " << po.timeout_s
      << " s, memory limit half the machine's) on the same points; its answer was normalised by its adapter "
         "(orientation, index base, duplicate copies, extra vertices) and judged by dtlab's exact checker against "
         "the *input* points. Verdicts: `delaunay` (proven the Delaunay tetrahedralization), `triangulation` (valid, "
         "some non-Delaunay facets), `flat-tets`, `invalid` (overlaps, gaps, inverted tets, broken or non-convex "
         "hull), `missing-points`, `extra-points`, `crashed`, `hung`, `refused`, `not-installed`. A refusal on an "
         "input that spans no volume is not counted as a failure.\n\n";
    o << "Sources: the " << families.size() << " fuzz families (`dtlab fuzz --list`) at n = ";
    for (std::size_t i = 0; i < family_sizes.size(); ++i) o << (i ? ", " : "") << family_sizes[i];
    o << "; surface (`-surface`) and winding-number volume (`-volume`) samples of CGAL demo meshes at n = ";
    for (std::size_t i = 0; i < mesh_sizes.size(); ++i) o << (i ? ", " : "") << mesh_sizes[i];
    o << (meshes.names.empty() ? " (none: " + meshes.note + ")" : "") << "; " << cases << " seeds per (source, size)"
      << (options.quick ? " — a quick run: few cases per cell, wide intervals" : "") << ".\n\n";
    o << "## Summary per peer\n\n";
    o << table_row({"peer", "version", "cases", "not delaunay", "share [95% CI]", "verdicts (not delaunay)"})
      << table_rule(6, 2);
    for (const auto& p : peers) {
      if (not_installed.count(p)) {
        o << table_row({"`" + p + "`", versions[p].get<std::string>(), "0", "-", "-", "not-installed"});
        continue;
      }
      const Cell& t = per_peer[p];
      const auto [lo, hi] = wilson_interval(t.failing, t.cases);
      std::string v;
      for (const auto& [name, k] : t.verdicts) v += (v.empty() ? "" : ", ") + name + " " + std::to_string(k);
      o << table_row(
          {"`" + p + "`", versions[p].get<std::string>(), std::to_string(t.cases), std::to_string(t.failing),
           percent(t.cases ? double(t.failing) / t.cases : 0) + " [" + percent(lo) + ", " + percent(hi) + "]",
           v.empty() ? "-" : v});
    }
  }

  // The table of shrunk failing inputs.
  void shrink_section(std::ostringstream& o) {
    o << "\n## Heatmap: share of non-delaunay verdicts (peer x source)\n\n"
         "Each cell: failing/cases and the Wilson 95% interval. The HTML report colours the cells.\n\n";
    o << "HEATMAP-TABLE\n\n";
    o << "## Smallest failing input per (peer, source)\n\n"
         "The first failing case of each (peer, source) at its smallest size (a hung case only when the pair has no "
         "other failure), shrunk by delta debugging to a subset with the same verdict. Budget: "
      << fmt("%.0f", shrink_stage_s) << " s of wall clock for the whole stage and at most " << shrink_runs
      << " peer runs per pair and pass, " << options.jobs
      << " pairs at a time. Pass one gives each pair, as it starts, the time left times the jobs over the pairs "
         "left; each later pass gives the time left the same way to the pairs the pass before stopped by time or "
         "runs, going on from their smallest failing input (passes: "
      << shrunk_stage.pass_seconds.size() << ", of ";
    for (std::size_t i = 0; i < shrunk_stage.pass_pairs.size(); ++i)
      o << (i ? ", " : "") << shrunk_stage.pass_pairs[i] << (shrunk_stage.pass_pairs[i] == 1 ? " pair" : " pairs")
        << " in " << fmt("%.1f", shrunk_stage.pass_seconds[i]) << " s";
    o << "). A hang shrinks under a short limit per try (10x the slowest answered run of that peer on that source, "
         "2 s at least, half the full limit at most; exceeding it counts as still hung), and its shrunk input is run "
         "once more in a fresh process under the full "
      << fmt("%g", po.timeout_s) << " s limit: when it does not hang there, the original input is saved ("
      << fmt("%.0f", shrunk_stage.reserved_seconds) << " s of the stage kept for these runs, "
      << fmt("%.1f", shrunk_stage.confirm_seconds)
      << " s used). Tries of gmsh, gmsh-hxt and scipy run in served helpers (their start costs more than a small "
         "run); `fresh` is the saved input judged again in a fresh process, as every counted verdict is. "
         "`minimal`: 1-minimal; else what stopped the shrink (`runs` or `time` budget spent; `hung`: saved "
         "unshrunk; `unconfirmed`: a hang's shrunk input that did not hang under the full limit, the original "
         "saved). Reproduce with the command in the sidecar .json, e.g. `dtlab oracle corpus/FILE.node --against "
         "PEER`.\n\n";
    o << table_row({"peer", "source", "verdict", "points", "shrunk to", "minimal", "passes, runs, s", "fresh", "file"})
      << table_rule(9, 3);
    std::vector<std::string> notes;
    for (const auto& [key, cell] : cells) {
      if (!cell.failing) continue;
      ++failing_cells;
      const PeerCase* c = cell.smallest;
      if (!c) {
        o << table_row({"`" + key.first + "`", key.second, "-", "-", "-", "-", "-", "-", "none saved"});
        continue;
      }
      ++saved;
      if (c->shrunk_minimal)
        ++shrunk;
      else
        ++stops[c->shrink_stop];
      std::string minimal = c->shrunk_minimal ? "yes" : "no: " + c->shrink_stop;
      if (c->hung_try_seconds > 0) minimal += " (tries under " + fmt("%.1f", c->hung_try_seconds) + " s)";
      if (!c->shrink_note.empty()) notes.push_back("`" + key.first + "` on " + key.second + ": " + c->shrink_note);
      o << table_row({"`" + key.first + "`", key.second, verdict_name(c->run.verdict), std::to_string(c->n),
                      std::to_string(c->shrunk_points), minimal,
                      std::to_string(c->shrink_passes) + ", " + std::to_string(c->shrink_runs) + ", " +
                          fmt("%.1f", c->shrink_seconds),
                      verdict_name(c->shrunk_verdict), "`" + c->corpus_file + "`"});
    }
    o << "\n"
      << failing_cells << " failing (peer, source) pairs, " << saved << " with an input saved, " << shrunk
      << " shrunk to 1-minimal";
    for (const auto& [why, k] : stops)
      o << ", " << k << " "
        << (why == "hung"          ? "saved unshrunk as hung"
            : why == "unconfirmed" ? "unconfirmed hangs"
                                   : "stopped by " + why + " budget");
    o << ".\n";
    for (const auto& n : notes) o << "\n- " << n;
    if (!notes.empty()) o << "\n";
  }

  // Speed and where the time went.
  void speed_section(std::ostringstream& o) {
    o << "\n## Speed (ratio to CGAL in the same run)\n\n"
         "Seconds: the triangulation as the peer times it (TetGen: its whole process, file reading and writing "
         "included; scipy: the `Delaunay()` call). Peak MB: the peer process's peak resident memory (for scipy "
         "the Python interpreter and numpy included); bytes/tet = peak / tets.\n\n";
    o << table_row({"source", "n", "peer", "verdict", "seconds", "x CGAL", "peak MB", "bytes/tet"}) << table_rule(8, 4);
    for (const auto& s : speed) {
      double cgal = 0;
      for (const auto& t : speed)
        if (t.source == s.source && t.n == s.n && t.run.name == "cgal" && !no_answer(t.run.verdict))
          cgal = t.run.seconds;
      const bool answered = !no_answer(s.run.verdict);
      const std::uint64_t tets = s.run.report ? s.run.report->stats.tets : 0;
      o << table_row({s.source, std::to_string(s.n), "`" + s.run.name + "`", verdict_name(s.run.verdict),
                      answered ? fmt("%.3f", s.run.seconds) : "-",
                      answered && cgal > 0 ? fmt("%.2f", s.run.seconds / cgal) : "-",
                      answered ? fmt("%.0f", s.run.peak_rss_bytes / 1e6) : "-",
                      answered && tets ? fmt("%.0f", double(s.run.peak_rss_bytes) / double(tets)) : "-"});
    }
    o << "\n## Where the time went\n\n"
         "Wall seconds of this run's stages (the machine's load changes them; see the environment below).\n\n";
    o << table_row({"stage", "seconds"}) << table_rule(2, 1);
    o << table_row({"runs (" + std::to_string(all.size()) + " cases, " + std::to_string(options.jobs) + " at a time)",
                    fmt("%.1f", stage_seconds["runs"].get<double>())});
    for (const auto& p : peers)
      if (const json& per_peer_seconds = stage_seconds["runs_process_seconds"]; per_peer_seconds.contains(p))
        o << table_row({"&nbsp;&nbsp;`" + p + "`: its processes' wall seconds, summed",
                        fmt("%.1f", per_peer_seconds[p].get<double>())});
    o << table_row({"shrinking (" + std::to_string(to_shrink.size()) + " pairs, " +
                        std::to_string(shrunk_stage.pass_seconds.size()) + " passes)",
                    fmt("%.1f", stage_seconds["shrinking"].get<double>())});
    o << table_row({"speed", fmt("%.1f", stage_seconds["speed"].get<double>())});
  }

  // Where the data is; the environment.
  void data_section(std::ostringstream& o) {
    o << "\n## Data\n\n`leaderboard.csv` (one row per case: peer, source, n, case, seed, verdict, defect counts, "
         "seconds, peak RSS, shrunk input), `data/speed.csv`, `corpus/` (shrunk failing inputs with sidecars), "
         "`environment.json` (machine, versions of every peer).\n\n";
    o << environment_markdown(env);
    if (peers.empty()) {
      o << "\nDelaunay peers: none (`--peers none`); the Voronoi peers' versions are in their table.\n";
      return;
    }
    o << "\nPeer versions: ";
    for (const auto& p : peers) o << "`" << p << "` " << versions[p].get<std::string>() << "; ";
    o << "\n";
  }

  // report.md and report.html, the heatmap put in (coloured in HTML).
  void write_reports(std::string md) const {
    // The heatmap as a Markdown table and as a coloured HTML table.
    std::ostringstream md_heat, html_heat;
    std::vector<std::string> installed;
    for (const auto& p : peers)
      if (!not_installed.count(p)) installed.push_back(p);
    std::vector<std::string> header = {"source"};
    for (const auto& p : installed) header.push_back(p);
    md_heat << table_row(header) << table_rule(header.size(), 1);
    html_heat << "<table class=\"heat\"><tr><th>source</th>";
    for (const auto& p : installed) html_heat << "<th>" << p << "</th>";
    html_heat << "</tr>\n";
    for (const auto& src : sources) {
      std::vector<std::string> row = {src};
      html_heat << "<tr><td>" << src << "</td>";
      for (const auto& p : installed) {
        const auto it = cells.find({p, src});
        if (it == cells.end() || !it->second.cases) {
          row.push_back("-");
          html_heat << "<td>-</td>";
          continue;
        }
        const Cell& c = it->second;
        const auto [lo, hi] = wilson_interval(c.failing, c.cases);
        const double share = double(c.failing) / c.cases;
        row.push_back(std::to_string(c.failing) + "/" + std::to_string(c.cases) + " [" + percent(lo) + "-" +
                      percent(hi) + "]");
        std::string title;
        for (const auto& [v, k] : c.verdicts) title += v + " " + std::to_string(k) + " ";
        html_heat << "<td style=\"background:" << heat_colour(share) << "\" title=\"" << title << "\">" << c.failing
                  << "/" << c.cases << "<br><small>" << percent(lo) << "&ndash;" << percent(hi) << "</small></td>";
      }
      md_heat << table_row(row);
      html_heat << "</tr>\n";
    }
    html_heat << "</table>\n";
    const std::string marker = "HEATMAP-TABLE";
    std::string html = markdown_to_html(md, "dtlab leaderboard");
    md.replace(md.find(marker), marker.size(), md_heat.str());
    if (const auto at = html.find("<p>" + marker + "</p>"); at != std::string::npos)
      html.replace(at, marker.size() + 7, html_heat.str());
    write_text(dir / "report.md", md);
    write_text(dir / "report.html", html);
  }

  // data/facts.json; exit 1 when a robust dtlab backend failed.
  ExperimentResult write_facts() {
    json facts = {{"cases", all.size()},
                  {"failing_cells", failing_cells},
                  {"shrunk_cells", shrunk},
                  {"saved_cells", saved},
                  {"shrink_stops", stops},
                  {"stage_seconds", stage_seconds},
                  {"robust_dtlab_failed", robust_failed},
                  {"quick", options.quick}};
    json per = json::object();
    for (const auto& [p, t] : per_peer) per[p] = {{"cases", t.cases}, {"not_delaunay", t.failing}};
    facts["peers"] = per;
    facts["not_installed"] = not_installed;
    if (!voronoi_facts.is_null()) facts["voronoi"] = voronoi_facts;
    facts["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    write_text_file((dir / "data" / "facts.json").string(), facts.dump(2) + "\n");
    return {robust_failed ? 1 : 0, facts};
  }

  // The Voronoi section (experiments/leaderboard_voronoi.hpp) on the same sources and
  // sizes; "" when no Voronoi peer is asked for.
  std::string voronoi_section() {
    if (options.voronoi_peers.empty() || options.voronoi_peers == std::vector<std::string>{"none"}) return "";
    const std::vector<std::string> vpeers = expand_voronoi_peer_names(options.voronoi_peers);
    step("Voronoi section");
    VoronoiBoardOptions v;
    v.peers = vpeers;
    v.sources = families;
    v.sources.insert(v.sources.end(), mesh_sources.begin(), mesh_sources.end());
    v.families = families.size();
    v.family_sizes = family_sizes;
    v.mesh_sizes = mesh_sizes;
    v.cases = cases;
    v.seed = options.seed;
    v.jobs = options.jobs;
    v.timeout_s = po.timeout_s;
    v.shrink_runs = shrink_runs;
    v.shrink_seconds = shrink_stage_s;
    v.speed_sources = fuzz_family_sources({"uniform"});
    if (!mesh_sources.empty()) v.speed_sources.push_back(mesh_sources[1]);
    v.speed_sizes = options.voronoi_speed_sizes.empty()
                        ? (options.quick ? std::vector<std::size_t>{10000} : std::vector<std::size_t>{100000})
                        : options.voronoi_speed_sizes;
    v.out_dir = dir.string();
    VoronoiBoard b = run_voronoi_board(v);
    voronoi_facts = b.facts;
    return b.markdown;
  }

  const LeaderboardOptions& options;
  const fs::path dir;
  const std::chrono::steady_clock::time_point t0;
  std::vector<std::string> peers;
  std::size_t cases = 0, shrink_runs = 0;
  double shrink_stage_s = 0;
  std::vector<std::size_t> family_sizes, mesh_sizes, speed_sizes;
  PeerOptions po;
  MeshSet meshes;
  std::vector<std::unique_ptr<MeshSampler>> samplers;
  std::vector<PointSource> families, mesh_sources;
  std::vector<PeerCase> all;
  std::vector<std::string> runnable;
  json stage_seconds = json::object();  // where the time went: runs per peer, shrinking, speed
  std::vector<ShrinkPair> to_shrink;
  ShrinkStageResult shrunk_stage;
  std::vector<SpeedRow> speed;
  std::vector<std::string> sources;
  std::map<std::pair<std::string, std::string>, Cell> cells;
  std::map<std::string, Cell> per_peer;
  std::map<std::string, std::string> not_installed;
  bool robust_failed = false;
  json env, versions;
  std::size_t failing_cells = 0, shrunk = 0, saved = 0;
  std::map<std::string, std::size_t> stops;
  json voronoi_facts;
};

}  // namespace

ExperimentResult run_leaderboard(const LeaderboardOptions& options) { return Leaderboard(options).run(); }

}  // namespace dtlab::experiments
