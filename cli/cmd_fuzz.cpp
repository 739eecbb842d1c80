// `dtlab fuzz`: degeneracy fuzz campaigns (fuzz/campaign.hpp), corpus replay, and
// the list of point-set families.
#include <charconv>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/build_options.hpp"
#include "cli/cli_error.hpp"
#include "cli/command.hpp"
#include "cli/fuzz_target.hpp"
#include "cli/number_options.hpp"
#include "cli/peer_definitions.hpp"
#include "cli/progress.hpp"
#include "fuzz/campaign.hpp"
#include "fuzz/campaign_report.hpp"
#include "fuzz/campaign_settings.hpp"
#include "fuzz/corpus.hpp"
#include "fuzz/families.hpp"
#include "fuzz/summary.hpp"
#include "kernel/canonical_order.hpp"
#include "kernel/input_error.hpp"
#include "kernel/output_file.hpp"
#include "kernel/point_io.hpp"
#include "oracle/check/check.hpp"
#include "oracle/check/compare.hpp"
#include "oracle/peers/peer_command.hpp"
#include "oracle/peers/peers.hpp"
#include "voronoi_check/voronoi_peers.hpp"

namespace dtlab::cli {

namespace {

struct FuzzArgs {
  std::string families = "all";
  std::size_t cases = 100;
  long long only_case = -1;
  std::uint64_t seed = 1;
  std::size_t min_points = 8, max_points = 64;
  bool min_points_given = false;  // an explicit --min-points above --points is refused
  std::string predicates = "adaptive";
  std::string perturb = "sos";
  KernelArgs kernel;  // --eps, --eps-mode, --boundary, --order (the seed is set per case)
  const CLI::Option* order_option = nullptr;  // --order: given, it overrides a replayed entry's
  std::string oracle = "none";
  const CLI::Option* against_option = nullptr;  // --against: given, it overrides a replayed entry's
  std::string target;  // a peer: judge it instead of dtlab
  unsigned jobs = 1;
  std::string out;
  std::string shard;
  std::string replay;
  bool no_shrink = false;
  std::size_t shrink_budget = 500;
  bool list = false;
  bool summarize_only = false;
  std::vector<std::string> summarize_dirs;
  bool json = false;
  bool quiet = false;
  bool predicates_given = false;
  PeerDefinitionArgs defined;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

[[noreturn]] void usage_error(const std::string& what) { throw UsageError(what); }

std::vector<PredicateSpec> backends_of(const FuzzArgs& a) {
  std::vector<PredicateSpec> specs;
  for (const auto& name : split(a.predicates)) {
    if (const std::string why = predicates_error(name); !why.empty()) usage_error(why);
    for (const auto& p : split(a.perturb)) {
      if (p != "none" && p != "sos") usage_error("unknown perturbation '" + p + "' (none, sos)");
      PredicateSpec spec;
      spec.backend = name;
      spec.perturb = p == "sos";
      spec.eps = a.kernel.eps;
      spec.relative_eps = a.kernel.eps_mode == "relative";
      specs.push_back(spec);
    }
  }
  if (specs.empty()) usage_error("no backend selected");
  return specs;
}

// --against serial (with --threads above 1): the threaded build against the serial one, tet
// for tet. Only for one backend with sos, where the tetrahedralization is unique (without
// perturbation two valid builds may differ; the checker judges those).
fuzz::OracleHook serial_hook(const std::vector<PredicateSpec>& backends, const BuildOptions& build) {
  if (build.threads == 1) usage_error("--against serial compares a threaded build: give --threads 0 or above 1");
  if (backends.size() != 1 || !backends[0].perturb)
    usage_error("--against serial needs exactly one backend, with --perturb sos (the only unique answer)");
  BuildOptions serial = build;
  serial.threads = 1;
  return {"serial", [spec = backends[0], serial](std::span<const Point3> points, const BuildResult& ours) -> std::string {
            if (ours.failure) return "";
            const BuildResult r = build_delaunay(points, spec, serial);
            if (r.failure) return "serial-failed";
            std::vector<Tet> tets = r.mesh.tets, mine = ours.mesh.tets;
            canonical_order(tets, points.size(), 1);
            canonical_order(mine, points.size(), 1);
            if (r.duplicates != ours.duplicates) return "duplicates-differ";
            return tets == mine ? "" : "tets-differ";
          }};
}

// The first of `names` that is no oracle ("none", "serial" or a peer's name), "" when all are.
std::string unknown_oracle(const std::vector<std::string>& names) {
  for (const auto& name : names)
    if (name != "none" && name != "serial" && !is_peer_name(name)) return name;
  return "";
}

std::string unknown_oracle_message(const std::string& name) {
  return "unknown oracle '" + name + "' (none, or peers: see dtlab oracle --help)";
}

// The hooks of oracle names (unknown_oracle(names) empty): the peers in their order, then
// `serial` (serial_hook) when named; "none" adds nothing. A campaign and a replay of its
// corpus build them alike.
std::vector<fuzz::OracleHook> oracle_hooks(const std::vector<std::string>& names,
                                           const std::vector<PredicateSpec>& backends, const BuildOptions& build) {
  std::vector<fuzz::OracleHook> hooks;
  for (const auto& name : names) {
    if (name == "none" || name == "serial") continue;
    // The peer runs in its own process and its answer counts only when the checker
    // proves it Delaunay: its crash, time-out or wrong answer is "no answer", never
    // ours. Ours is compared canonically (Delaunay complex; tets in general position).
    hooks.push_back({name, [name](std::span<const Point3> points, const BuildResult& ours) -> std::string {
      if (ours.failure) return "";
      const PeerRun run = run_peer(name, points);
      if (run.verdict != Verdict::delaunay) return "";
      CheckOptions ours_opt;
      ours_opt.duplicates = ours.duplicates;
      const CheckReport mine = check_tetrahedralization(ours.mesh, ours_opt);
      if (!mine.ok()) return "";
      return compare_canonical(ours.mesh, mine, *run.mesh, *run.report).agree() ? "" : "differs-from-" + name;
    }});
  }
  if (std::find(names.begin(), names.end(), "serial") != names.end()) hooks.push_back(serial_hook(backends, build));
  return hooks;
}

// --shard K/N: two integers in digits, 0 <= K < N < 2^32 (no wrap, no sign).
std::pair<unsigned, unsigned> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  unsigned k = 0, n = 0;
  const auto whole = [](std::string_view s, unsigned& v) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && ec == std::errc() && p == s.data() + s.size();
  };
  if (slash == std::string::npos || !whole(std::string_view(text).substr(0, slash), k) ||
      !whole(std::string_view(text).substr(slash + 1), n) || n == 0 || k >= n)
    usage_error("bad --shard '" + text + "' (K/N in digits with 0 <= K < N < 2^32)");
  return {k, n};
}

void check_min_points(const FuzzArgs& a) {
  if (a.min_points_given && a.min_points > a.max_points)
    usage_error("--min-points " + std::to_string(a.min_points) + " is above --points " + std::to_string(a.max_points));
}

// `--target PEER` (cli/fuzz_target.hpp): the campaign's arguments from the command's.
TargetArgs target_args(const FuzzArgs& a, const std::string& target, const std::vector<std::string>& families) {
  check_min_points(a);
  TargetArgs t;
  t.target = target;
  t.families = families;
  t.cases = a.cases;
  if (a.only_case >= 0) t.only_case = static_cast<std::size_t>(a.only_case);
  t.seed = a.seed;
  t.min_points = a.min_points;
  t.max_points = a.max_points;
  t.out = a.out;
  t.shrink = !a.no_shrink;
  t.shrink_budget = a.shrink_budget;
  t.jobs = a.jobs ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
  t.json = a.json;
  t.quiet = a.quiet;
  return t;
}

// A Voronoi peer by its name, or by voronoi:NAME where the name is a DT peer's too
// (dtlab:B); else a DT peer. Its failures are shrunk into the corpus.
int run_target(const FuzzArgs& a, const std::vector<std::string>& families) {
  const std::string voronoi_target = a.target.rfind("voronoi:", 0) == 0 ? a.target.substr(8) : a.target;
  if (is_voronoi_peer_name(voronoi_target) && (voronoi_target != a.target || !is_peer_name(a.target)))
    return run_voronoi_target(target_args(a, voronoi_target, families));
  if (!is_peer_name(a.target)) usage_error("unknown peer '" + a.target + "' (see dtlab oracle --help)");
  return run_peer_target(target_args(a, a.target, families));
}

std::string point_text(const Point3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", p.x, p.y, p.z);
  return buf;
}

// The checker's witness of a failing replay: its detail, the defect counts, the
// tets and the input points (index and exact coordinates) it names.
nlohmann::json witness_json(const fuzz::ReplayResult& r) {
  nlohmann::json points = nlohmann::json::array();
  if (!r.run.witness_vertices.empty()) {
    const auto input = read_points(r.file).points;
    for (auto v : r.run.witness_vertices)
      if (v < input.size()) points.push_back({{"index", v}, {"xyz", {input[v].x, input[v].y, input[v].z}}});
  }
  return {{"detail", r.run.detail}, {"defects", r.run.defects}, {"tets", r.run.witness_tets}, {"points", points}};
}

void print_witness(const fuzz::ReplayResult& r) {
  if (!r.run.defects.empty()) {
    std::string counts;
    for (const auto& [kind, n] : r.run.defects) {
      if (!counts.empty()) counts += ", ";
      counts += kind;
      counts += ' ';
      counts += std::to_string(n);
    }
    std::printf("         defects: %s\n", counts.c_str());
  }
  if (!r.run.detail.empty())
    std::printf("         %s: %s\n", r.run.defects.empty() ? "failure" : "witness", r.run.detail.c_str());
  if (!r.run.witness_tets.empty()) {
    std::string tets;
    for (auto t : r.run.witness_tets) {
      tets += ' ';
      tets += std::to_string(t);
    }
    std::printf("         tets:%s\n", tets.c_str());
  }
  if (!r.run.witness_vertices.empty()) {
    const auto input = read_points(r.file).points;
    for (auto v : r.run.witness_vertices)
      if (v < input.size()) std::printf("         point %u %s\n", v, point_text(input[v]).c_str());
  }
}

int run_replay(const FuzzArgs& a) {
  fuzz::ReplayOptions options;
  if (a.predicates_given) options.backends = backends_of(a);
  if (a.kernel.boundary != "infinite") options.boundary = a.kernel.build_options();
  // Each entry is rebuilt with its sidecar's order and threads unless these are given.
  if (a.order_option && a.order_option->count() > 0) options.order = a.kernel.build_options().order;
  if (a.kernel.threads_option && a.kernel.threads_option->count() > 0) options.threads = a.kernel.threads;
  if (a.against_option && a.against_option->count() > 0) {
    const auto names = split(a.oracle);
    // An unknown name is a usage error, before any entry runs.
    if (const std::string bad = unknown_oracle(names); !bad.empty()) usage_error(unknown_oracle_message(bad));
    options.against.emplace();
    for (const auto& name : names)
      if (name != "none") options.against->push_back(name);
  }
  // An entry compared with oracles is compared with them again (its sidecar's "against"),
  // built as the campaign built them: the same hooks for the entry's backend and build.
  options.oracles = [](const std::vector<std::string>& names, const PredicateSpec& spec, const BuildOptions& build) {
    if (const std::string bad = unknown_oracle(names); !bad.empty())
      throw std::invalid_argument(unknown_oracle_message(bad));
    return oracle_hooks(names, {spec}, build);
  };
  const auto results = fuzz::replay_corpus(a.replay, options);
  std::size_t failing = 0;
  nlohmann::json lines = nlohmann::json::array();
  for (const auto& r : results) {
    failing += !r.run.ok();
    if (a.json) {
      nlohmann::json line = {
          {"file", r.file},       {"backend", r.backend},     {"boundary", r.boundary},
          {"order", r.order},     {"threads", r.threads},     {"parallel_passes", r.run.parallel_passes},
          {"against", r.against}, {"outcome", r.run.outcome}, {"recorded", r.recorded_outcome},
          {"ok", r.run.ok()},     {"detail", r.run.detail},   {"defects", r.run.defects}};
      if (!r.run.ok()) line["witness"] = witness_json(r);
      lines.push_back(std::move(line));
    } else {
      // The file with the settings it was built with: `dtlab fuzz --replay` and this line's
      // tail is the same build.
      std::string against;
      for (const auto& n : r.against) against += (against.empty() ? " --against " : ",") + n;
      std::printf("%-8s %-14s %-24s %s --order %s --threads %u%s%s\n", r.run.ok() ? "ok" : "FAIL", r.backend.c_str(),
                  r.run.outcome.c_str(), r.file.c_str(), r.order.c_str(), r.threads, against.c_str(),
                  r.recorded_outcome.empty() ? "" : (" (recorded: " + r.recorded_outcome + ")").c_str());
      if (!r.run.ok()) print_witness(r);
    }
  }
  if (a.json) {
    std::cout << nlohmann::json{{"replayed", results.size()}, {"failing", failing}, {"results", lines}}.dump(2)
              << "\n";
  } else {
    std::printf("%zu replayed, %zu failing\n", results.size(), failing);
  }
  return failing ? kDefect : kOk;
}

void print_summary(const std::vector<fuzz::CaseRecord>& records, bool json, std::size_t ran,
                   std::size_t resumed) {
  const fuzz::Summary s = fuzz::summarize(records);
  if (json) {
    auto j = fuzz::summary_json(s);
    j["ran"] = ran;
    j["resumed"] = resumed;
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << fuzz::summary_table(s);
    std::size_t failing = 0;
    for (const auto& r : records) failing += !r.run.ok();
    std::printf("%zu results (%zu cases run now, %zu resumed), %zu failing\n", records.size(), ran,
                resumed, failing);
  }
}

// `--summarize [DIR...]`: the merged summary of campaign folders (shards), written
// as summary.md / summary.json into --out (default: the one DIR). Exit 0 once written,
// whatever the results say; 2 when a folder has no results.
int run_summarize(const FuzzArgs& a) {
  std::vector<std::string> dirs;
  for (const auto& d : a.summarize_dirs)
    if (!d.empty()) dirs.push_back(d);  // `--summarize` given without a value may leave ""
  if (dirs.empty() && !a.out.empty()) dirs.push_back(a.out);
  if (dirs.empty()) usage_error("--summarize needs campaign folders (or --out DIR)");
  for (const auto& d : dirs)
    if (fuzz::read_records(d).empty()) throw InputError(d, 0, "no campaign results (results*.jsonl) in this folder");
  const auto records = fuzz::read_campaigns(dirs);
  const std::string out = !a.out.empty() ? a.out : dirs.size() == 1 ? dirs.front() : "";
  if (out.empty()) usage_error("--summarize with several folders needs --out DIR for the merged summary");
  std::filesystem::create_directories(out);
  fuzz::write_summary_files(out, fuzz::summarize(records));
  if (std::find(dirs.begin(), dirs.end(), out) == dirs.end()) {
    const nlohmann::json env = {{"merged_from", dirs}, {"environments", fuzz::read_environments(dirs)}};
    write_text_file(out + "/environment.json", env.dump(2) + "\n");
  }
  print_summary(records, a.json, 0, records.size());
  if (!a.json) std::printf("wrote %s/summary.md and summary.json\n", out.c_str());
  return kOk;
}

int run_fuzz(const FuzzArgs& a) {
  if (a.list) {
    for (const auto& f : fuzz::families()) std::printf("%-16s %s\n", f.name.c_str(), f.description.c_str());
    return kOk;
  }
  a.defined.register_all();  // peers by command: a replay's oracles may be among them
  if (!a.replay.empty()) return run_replay(a);
  if (a.summarize_only) return run_summarize(a);
  if (a.out.empty()) usage_error("--out DIR is required (or --replay, --list, --summarize DIR)");

  fuzz::CampaignOptions o;
  if (a.families == "all") {
    for (const auto& f : fuzz::families()) o.families.push_back(f.name);
  } else {
    o.families = split(a.families);
    for (const auto& name : o.families)
      if (!fuzz::find_family(name)) usage_error("unknown family '" + name + "' (see dtlab fuzz --list)");
  }
  if (!a.target.empty()) return run_target(a, o.families);
  o.cases = a.cases;
  if (a.only_case >= 0) {
    o.only_case = static_cast<std::size_t>(a.only_case);
    o.cases = std::max(o.cases, *o.only_case + 1);
  }
  if (a.max_points < 1) usage_error("--points must be at least 1");
  check_min_points(a);
  o.max_points = a.max_points;
  o.min_points = std::min(a.min_points, a.max_points);
  o.seed = a.seed;
  o.backends = backends_of(a);
  o.build = a.kernel.build_options();  // boundary and order; the seed is set per case
  // Threaded builds split every case across the threads, however small it is (as the
  // replay of the corpus builds them: fuzz/campaign_settings.hpp).
  fuzz::use_build_threads(o.build, o.build.threads);
  const auto oracle_names = split(a.oracle);
  if (const std::string bad = unknown_oracle(oracle_names); !bad.empty()) usage_error(unknown_oracle_message(bad));
  o.oracles = oracle_hooks(oracle_names, o.backends, o.build);
  o.jobs = a.jobs ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
  o.out_dir = a.out;
  if (!a.shard.empty()) {
    const auto [k, n] = parse_shard(a.shard);
    o.shard = k;
    o.shards = n;
  }
  o.shrink = !a.no_shrink;
  o.shrink_budget = a.shrink_budget;
  Progress progress("fuzz", a.quiet);
  o.progress = [&progress](std::size_t done, std::size_t total, std::size_t failing) {
    progress.update("cases", done, total, std::to_string(failing) + " failing");
  };

  const fuzz::CampaignResult result = fuzz::run_campaign(o);
  print_summary(result.records, a.json, result.ran, result.resumed);
  return result.failing() ? kDefect : kOk;
}

}  // namespace

void add_fuzz_command(CLI::App& app, int& rc) {
  auto args = std::make_shared<FuzzArgs>();
  CLI::App* sub = app.add_subcommand("fuzz", "degeneracy fuzz campaigns: generate, build, check, shrink");
  sub->add_option("--family", args->families, "all, or a comma-separated list (see --list)");
  sub->add_option("--cases", args->cases, "cases per family")->transform(count_in(1, 1e12))->capture_default_str();
  sub->add_option("--case", args->only_case, "run only this case index (reproduces one case)")
      ->transform(count_in(0, 1e15))
      ->default_str("all");
  sub->add_option("--seed", args->seed, "campaign seed")->check(seed_value())->capture_default_str();
  sub->add_option("--points", args->max_points, "largest number of points per case")->transform(count_in(1, 1e7))->capture_default_str();
  sub->add_option("--min-points", args->min_points, "smallest number of points per case")->transform(count_in(1, 1e7))->each([args](const std::string&) { args->min_points_given = true; })->capture_default_str();
  auto* pred = sub->add_option("--predicates", args->predicates,
                               "comma list of naive, epsilon, adaptive, exact, plugin:PATH.so")
                   ->capture_default_str();
  sub->add_option("--perturb", args->perturb, "comma list of none, sos")->capture_default_str();
  args->kernel.add_to(*sub, kEpsOption | kBoundaryOption | kOrderOption | kThreadsOption);
  args->order_option = sub->get_option("--order");
  sub->add_flag_callback(
      "--relative-eps", [args] { args->kernel.eps_mode = "relative"; }, "the old spelling of --eps-mode relative");
  args->against_option =
      sub->add_option(
             "--against,--oracle", args->oracle,
             "none, or a comma list of peers to compare with (cgal, tetgen, qhull, ...), as in `dtlab oracle`; "
             "serial: a --threads build against the serial build, tet for tet (one backend, sos); "
             "with --replay: instead of each entry's recorded oracles; --oracle is the old spelling")
          ->capture_default_str();
  sub->add_option(
      "--target", args->target,
      "judge this peer instead of dtlab (cgal, qhull, scipy, gmsh, ...; or a Voronoi peer: voro++, "
      "scipy-voronoi, qvoronoi, cgal-dual, voronoi:dtlab:B); its failures are shrunk into the corpus. Exit 1 "
      "when it failed, 3 when it is not installed");
  args->defined.add_to(*sub, "--peers,--peers-file", PeerKinds::both);
  sub->add_option("--jobs", args->jobs, "worker threads (0: one per core)")->transform(count_in(0, 1024))->capture_default_str();
  sub->add_option("--out", args->out, "campaign folder (results*.jsonl, corpus/, summary.md, environment.json)")
      ->type_name("DIR");
  sub->add_option("--shard", args->shard, "K/N: run only the cases with ordinal % N == K");
  sub->add_option("--replay", args->replay,
                  "re-run a corpus: a .node file, a corpus or campaign folder; each entry is built with its "
                  "sidecar's backend, boundary, order and threads (--predicates, --boundary, --order, --threads "
                  "given: those)");
  sub->add_flag("--no-shrink", args->no_shrink, "do not shrink failing cases");
  sub->add_option("--shrink-budget", args->shrink_budget, "builds per shrunk case")->transform(count_in(0, 1e9))->capture_default_str();
  sub->add_flag("--list", args->list, "list the point-set families and what each targets");
  auto* summarize = sub->add_option("--summarize", args->summarize_dirs,
                                    "[DIR...] merge the results of campaign folders (shards; default --out) into "
                                    "summary.md and summary.json in --out, without running")
                        ->expected(0, -1);
  sub->add_flag("--json", args->json, "print a JSON summary on stdout");
  sub->add_flag("--quiet", args->quiet, "no progress lines on stderr");
  sub->callback([args, pred, summarize, &rc] {
    args->predicates_given = pred->count() > 0;
    args->summarize_only = summarize->count() > 0;
    rc = run_fuzz(*args);
  });
}

}  // namespace dtlab::cli
