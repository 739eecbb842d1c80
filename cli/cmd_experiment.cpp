// dtlab experiment: reproducible experiments that write a report folder.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli/build_options.hpp"
#include "cli/cli_error.hpp"
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/peer_definitions.hpp"
#include "cli/stdout_to_stderr.hpp"
#include "experiments/benchmark.hpp"
#include "experiments/leaderboard.hpp"
#include "experiments/thesis_failures.hpp"
#include "oracle/peers/peer_command.hpp"
#include "voronoi_check/voronoi_peer_command.hpp"

namespace dtlab::cli {

namespace {

std::string command_line(const std::string& sub, const std::vector<std::string>& args) {
  std::string s = "dtlab experiment " + sub;
  for (const auto& a : args) s += " " + a;
  return s;
}

// Runs one experiment; with --json its own output goes to stderr and stdout gets
// {"report", "exit", "facts"} (facts: the report's data/facts.json, its headline numbers).
template <class Run>
int run_experiment(bool json, const std::filesystem::path& out, Run&& run) {
  int code;
  {
    StdoutToStderr quiet(json);
    code = run();  // an exception is reported by main() (cli/cli_error.hpp), exit 2
    std::printf("report: %s\n", (out / "report.md").string().c_str());
  }
  if (json) {
    nlohmann::json j = {{"report", (out / "report.md").string()}, {"exit", code}};
    std::ifstream facts(out / "data" / "facts.json");
    if (facts) j["facts"] = nlohmann::json::parse(facts, nullptr, false);
    std::printf("%s\n", j.dump(2).c_str());
  }
  return code;
}

// `experiment thesis-failures`: the thesis's robustness failures (chapter 5).
void add_thesis_failures_command(CLI::App* sub, int& rc) {
  auto thesis = std::make_shared<experiments::ThesisFailuresOptions>();
  thesis->out = "reports/thesis-failures";
  auto no_figures = std::make_shared<bool>(false);
  CLI::App* t = sub->add_subcommand("thesis-failures", "reproduce and measure the thesis's robustness failures (chapter 5)");
  auto thesis_quiet = std::make_shared<bool>(false);
  t->add_option("--out", thesis->out, "report folder")->type_name("DIR")->capture_default_str();
  t->add_flag("--quick", thesis->quick, "fewer sizes and cases (seconds instead of minutes)");
  t->add_option("--seed", thesis->seed, "experiment seed")->check(seed_value())->capture_default_str();
  t->add_flag("--no-figures", *no_figures, "skip the matplotlib figures");
  t->add_option("--extra-predicates", thesis->extra_predicates,
                "more backends for the failure-rate table, without sos (plugin:PATH.so, ...)")
      ->delimiter(',')
      ->check(CLI::Validator(predicates_error, "BACKEND"));
  auto thesis_json = std::make_shared<bool>(false);
  t->add_flag("--json", *thesis_json, "print a JSON summary (the report's headline facts) on stdout");
  t->add_flag("--quiet", *thesis_quiet, "no progress lines on stderr");
  t->callback([thesis, no_figures, thesis_json, thesis_quiet, t, &rc] {
    thesis->figures = !*no_figures;
    thesis->progress = !*thesis_quiet;
    std::vector<std::string> args = {"--out", thesis->out.string(), "--seed", std::to_string(thesis->seed)};
    if (thesis->quick) args.push_back("--quick");
    if (*no_figures) args.push_back("--no-figures");
    for (const auto& p : thesis->extra_predicates) args.insert(args.end(), {"--extra-predicates", p});
    thesis->command_line = command_line(t->get_name(), args);
    rc = run_experiment(*thesis_json, thesis->out, [&] { return experiments::run_thesis_failures(*thesis).exit_code; });
  });
}

// `experiment benchmark`: dtlab vs CGAL vs TetGen, predicate costs.
void add_benchmark_command(CLI::App* sub, int& rc) {
  auto bench = std::make_shared<experiments::BenchmarkOptions>();
  bench->out = "reports/benchmark";
  auto bench_no_figures = std::make_shared<bool>(false);
  CLI::App* b = sub->add_subcommand("benchmark", "time and memory of dtlab vs CGAL vs TetGen, predicate costs");
  auto bench_quiet = std::make_shared<bool>(false);
  b->add_option("--out", bench->out, "report folder")->type_name("DIR")->capture_default_str();
  b->add_flag("--large", bench->large, "also n = 10^7 uniform and 10^6 for the other distributions");
  b->add_flag("--quick", bench->quick, "n up to 10^4, fewer predicate calls (seconds instead of minutes)");
  b->add_option("--runs", bench->runs, "runs per tool and size for n <= 10^5 (larger n: 1 run)")
      ->transform(count_in(1, 1000))->capture_default_str();
  b->add_option("--points-seed,--seed", bench->seed, "seed of the generated points (--seed: the old spelling)")
      ->capture_default_str();
  b->add_option("--max-n", bench->max_n, "largest n, at least 4 (0: 10^6; 10^7 with --large, 10^4 with --quick)")->transform(count_in(0, 1e9));
  b->add_flag("--no-figures", *bench_no_figures, "skip the matplotlib figures");
  auto bench_json = std::make_shared<bool>(false);
  b->add_flag("--json", *bench_json, "print a JSON summary (the report's headline facts) on stdout");
  b->add_flag("--quiet", *bench_quiet, "no progress lines on stderr");
  b->callback([bench, bench_no_figures, bench_json, bench_quiet, b, &rc] {
    if (bench->max_n > 0 && bench->max_n < 4) throw UsageError("--max-n must be 0 or at least 4");
    bench->figures = !*bench_no_figures;
    bench->progress = !*bench_quiet;
    std::vector<std::string> args = {"--out", bench->out.string(), "--runs", std::to_string(bench->runs), "--points-seed",
                                     std::to_string(bench->seed)};
    if (bench->large) args.push_back("--large");
    if (bench->quick) args.push_back("--quick");
    if (bench->max_n) args.insert(args.end(), {"--max-n", std::to_string(bench->max_n)});
    if (*bench_no_figures) args.push_back("--no-figures");
    bench->command_line = command_line(b->get_name(), args);
    rc = run_experiment(*bench_json, bench->out, [&] { return experiments::run_benchmark(*bench).exit_code; });
  });
}

// Every defined Voronoi peer gets its own row in the Voronoi section ("all" has them).
void add_defined_voronoi_peers(const std::vector<std::string>& defined, std::vector<std::string>& peers) {
  if (defined.empty() || std::find(peers.begin(), peers.end(), "all") != peers.end()) return;
  if (peers == std::vector<std::string>{"none"}) peers.clear();
  for (const auto& name : defined)
    if (std::find(peers.begin(), peers.end(), name) == peers.end()) peers.push_back(name);
}

// `experiment leaderboard`: the field's Delaunay codes judged by the exact checker.
void add_leaderboard_command(CLI::App* sub, int& rc) {
  auto board = std::make_shared<experiments::LeaderboardOptions>();
  auto board_json = std::make_shared<bool>(false);
  auto board_no_meshes = std::make_shared<bool>(false);
  CLI::App* l = sub->add_subcommand(
      "leaderboard", "judge the field's Delaunay codes (CGAL, TetGen, qhull, scipy, gmsh, dtlab) with the exact checker");
  auto board_quiet = std::make_shared<bool>(false);
  l->add_option("--out", board->out, "report folder")->type_name("DIR")->capture_default_str();
  l->add_flag("--quick", board->quick, "2 cases per cell, one size per kind, speed at 10^4, short shrinks");
  l->add_option("--peers", board->peers, "peers to judge, or all")->delimiter(',');
  auto board_defined = std::make_shared<PeerDefinitionArgs>();
  board_defined->add_to(*l, "--peers-file", PeerKinds::both);
  l->add_option("--family,--families", board->families,
                "fuzz families, as fuzz --family (none given: all; --families is the old spelling)")
      ->delimiter(',');
  l->add_option("--cases", board->cases, "seeds per (source, size) (0: 2 with --quick, 3 otherwise)")
      ->transform(count_in(0, 1e6));
  l->add_option("--seed", board->seed, "experiment seed")->check(seed_value())->capture_default_str();
  l->add_option("--jobs", board->jobs, "peer runs at a time")->transform(count_in(1, 1024))->capture_default_str();
  l->add_option("--timeout", board->timeout_s, "seconds per peer run (0: 10 with --quick, 30 otherwise)")
      ->check(number_in(0, 1e6));
  l->add_option("--shrink-runs", board->shrink_runs,
                "peer runs per shrunk (peer, source) and pass (0: 48 with --quick, 300 otherwise)")
      ->transform(count_in(0, 1e9));
  l->add_option("--shrink-seconds", board->shrink_seconds,
                "wall-clock budget of the whole shrink stage (0: 30 with --quick, 600 otherwise)")
      ->check(number_in(0, 1e6));
  l->add_option("--speed-n", board->speed_n, "one size for the speed table (0: 10^5 and 10^6; 10^4 with --quick)")
      ->transform(count_in(0, 1e9));
  l->add_option("--voronoi-peers", board->voronoi_peers,
                "Voronoi peers of the Voronoi section (voro++, scipy-voronoi, qvoronoi, cgal-dual, dtlab:B), all, "
                "or none")
      ->delimiter(',');
  l->add_option("--voronoi-speed", board->voronoi_speed_sizes,
                "sizes of the Voronoi speed table (default 100000; 10000 with --quick; 1000000 is slow)")
      ->delimiter(',')
      ->transform(count_in(1, 1e9));
  l->add_flag("--no-meshes", *board_no_meshes, "leave out the CGAL demo mesh samples");
  l->add_option("--cgal-data", board->cgal_data, "CGAL demo data.tar.gz (default: libcgal-demo's)")->check(CLI::ExistingFile);
  l->add_flag("--json", *board_json, "print a JSON summary (the report's headline facts) on stdout");
  l->add_flag("--quiet", *board_quiet, "no progress lines on stderr");
  l->callback([board, board_json, board_no_meshes, board_quiet, board_defined, l, &rc] {
    // Every defined peer gets its own row.
    const std::vector<std::string> defined = board_defined->register_all();
    for (const auto& name : defined)
      if (std::find(board->peers.begin(), board->peers.end(), name) == board->peers.end() &&
          std::find(board->peers.begin(), board->peers.end(), "all") == board->peers.end())
        board->peers.push_back(name);
    add_defined_voronoi_peers(board_defined->voronoi_names(), board->voronoi_peers);
    board->meshes = !*board_no_meshes;
    board->progress = !*board_quiet;
    std::vector<std::string> args = {"--out", board->out.string(), "--seed", std::to_string(board->seed)};
    if (board->quick) args.push_back("--quick");
    if (board->cases) args.insert(args.end(), {"--cases", std::to_string(board->cases)});
    if (board->speed_n) args.insert(args.end(), {"--speed-n", std::to_string(board->speed_n)});
    if (board->timeout_s > 0) args.insert(args.end(), {"--timeout", number_options_detail::fmt(board->timeout_s)});
    if (board->shrink_runs) args.insert(args.end(), {"--shrink-runs", std::to_string(board->shrink_runs)});
    if (board->shrink_seconds > 0) args.insert(args.end(), {"--shrink-seconds", number_options_detail::fmt(board->shrink_seconds)});
    if (board->jobs != 2) args.insert(args.end(), {"--jobs", std::to_string(board->jobs)});
    if (*board_no_meshes) args.push_back("--no-meshes");
    const auto join = [](const std::vector<std::string>& v) {
      std::string s;
      for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
      return s;
    };
    if (board->peers != std::vector<std::string>{"all"}) args.insert(args.end(), {"--peers", join(board->peers)});
    if (!board->families.empty()) args.insert(args.end(), {"--family", join(board->families)});
    if (board->voronoi_peers != std::vector<std::string>{"all"})
      args.insert(args.end(), {"--voronoi-peers", join(board->voronoi_peers)});
    if (!board->voronoi_speed_sizes.empty()) {
      std::vector<std::string> sizes;
      for (auto n : board->voronoi_speed_sizes) sizes.push_back(std::to_string(n));
      args.insert(args.end(), {"--voronoi-speed", join(sizes)});
    }
    // Each defined peer as a quoted --peer, so the recorded command runs as it is.
    for (const auto& name : defined) args.push_back(peer_definition_arguments(name).substr(1));
    for (const auto& name : board_defined->voronoi_names())
      args.push_back(voronoi_peer_definition_arguments(name).substr(1));
    board->command_line = command_line(l->get_name(), args);
    rc = run_experiment(*board_json, board->out, [&] { return experiments::run_leaderboard(*board).exit_code; });
  });
}

}  // namespace

void add_experiment_command(CLI::App& app, int& rc) {
  CLI::App* sub =
      app.add_subcommand("experiment", "reproducible experiments with reports (report.md/.html, figures, data)");
  sub->require_subcommand(1);
  add_thesis_failures_command(sub, rc);
  add_benchmark_command(sub, rc);
  add_leaderboard_command(sub, rc);
}

}  // namespace dtlab::cli
