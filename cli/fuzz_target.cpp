#include "cli/fuzz_target.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/progress.hpp"
#include "experiments/peer_campaign.hpp"
#include "experiments/voronoi_campaign.hpp"
#include "oracle/peers/peer_command.hpp"
#include "voronoi_check/voronoi_peer_command.hpp"

namespace dtlab::cli {

namespace {

// What the report needs of one case, whichever campaign ran it.
struct TargetCase {
  std::string source;
  std::size_t index = 0, n = 0;
  std::string tally;    // the name it is counted under in its family's verdicts
  std::string verdict;  // the peer's verdict
  std::string message;
  bool failed = false, not_installed = false;
  std::string corpus_file;  // relative to --out; "" when not saved
  std::size_t shrunk_points = 0;
  std::optional<bool> minimal;  // whether the shrunk input is 1-minimal, where the campaign says
};

// How one campaign's failure is replayed: `<replay> <out>/<file> --against <target><suffix>`.
struct Replay {
  std::string command, suffix;
};

void set_grid(experiments::CaseGrid& o, const TargetArgs& a) {
  o.sources = experiments::fuzz_family_sources(a.families);
  o.cases = a.only_case ? std::max(a.cases, *a.only_case + 1) : a.cases;
  o.only_case = a.only_case;
  o.min_points = std::min(a.min_points, a.max_points);
  o.max_points = a.max_points;
  o.seed = a.seed;
  o.out_dir = a.out;
  o.shrink = a.shrink;
  o.shrink_budget = a.shrink_budget;
  o.jobs = a.jobs;
}

// Runs the campaign with a progress line (cases done, failing) on stderr.
template <class Case, class Options>
std::vector<Case> run_with_progress(Options& o, const TargetArgs& a, std::vector<Case> (*run)(const Options&)) {
  const std::size_t total = a.only_case ? o.sources.size() : o.cases * o.sources.size();
  Progress progress("fuzz", a.quiet);
  std::size_t done = 0, failed = 0;
  o.on_case = [&](const Case& c) {
    failed += c.failed();
    progress.update("cases", ++done, total, std::to_string(failed) + " failing");
  };
  return run(o);
}

nlohmann::json failure_json(const TargetCase& c) {
  nlohmann::json f = {{"source", c.source},
                      {"case", c.index},
                      {"n", c.n},
                      {"verdict", c.verdict},
                      {"message", c.message},
                      {"corpus_file", c.corpus_file},
                      {"shrunk_points", c.shrunk_points}};
  if (c.minimal) f["minimal"] = *c.minimal;
  return f;
}

struct FamilyRow {
  std::size_t cases = 0, failing = 0;
  std::map<std::string, std::size_t> verdicts;
};

void print_table(const TargetArgs& a, const std::map<std::string, FamilyRow>& rows,
                 const std::vector<TargetCase>& cases, const Replay& replay) {
  std::printf("%-18s %6s %8s  %s\n", "family", "cases", "failing", "verdicts");
  for (const auto& [src, r] : rows) {
    std::string v;
    for (const auto& [name, k] : r.verdicts) v += (v.empty() ? "" : ", ") + name + " " + std::to_string(k);
    std::printf("%-18s %6zu %8zu  %s\n", src.c_str(), r.cases, r.failing, v.c_str());
  }
  for (const TargetCase& c : cases)
    if (c.failed && !c.corpus_file.empty())
      std::printf("  %s case %zu: %s, shrunk to %zu points%s: %s/%s (%s %s/%s --against %s%s)\n", c.source.c_str(),
                  c.index, c.verdict.c_str(), c.shrunk_points, c.minimal.value_or(false) ? " (1-minimal)" : "",
                  a.out.c_str(), c.corpus_file.c_str(), replay.command.c_str(), a.out.c_str(), c.corpus_file.c_str(),
                  a.target.c_str(), replay.suffix.c_str());
}

// The per-family table (or --json) and the exit code: 3 when the peer is not
// installed (no case ran), 1 when a case failed.
int report(const TargetArgs& a, const std::vector<TargetCase>& cases, const Replay& replay) {
  std::map<std::string, FamilyRow> rows;
  nlohmann::json failures = nlohmann::json::array();
  std::size_t failing = 0, not_installed = 0;
  for (const TargetCase& c : cases) {
    FamilyRow& r = rows[c.source];
    ++r.cases;
    ++r.verdicts[c.tally];
    not_installed += c.not_installed;
    if (!c.failed) continue;
    ++r.failing, ++failing;
    failures.push_back(failure_json(c));
  }
  if (a.json) {
    nlohmann::json j = {{"target", a.target},
                        {"cases", cases.size()},
                        {"failing", failing},
                        {"not_installed", not_installed},
                        {"failures", failures}};
    for (const auto& [src, r] : rows)
      j["families"][src] = {{"cases", r.cases}, {"failing", r.failing}, {"verdicts", r.verdicts}};
    std::cout << j.dump(2) << "\n";
  } else {
    print_table(a, rows, cases, replay);
    std::printf("%s: %zu cases, %zu failing%s\n", a.target.c_str(), cases.size(), failing,
                not_installed ? " (not installed)" : "");
  }
  if (not_installed == cases.size() && !cases.empty()) return 3;
  return failing ? kDefect : kOk;
}

}  // namespace

int run_peer_target(const TargetArgs& a) {
  experiments::PeerCampaignOptions o;
  o.peer = a.target;
  set_grid(o, a);
  std::vector<TargetCase> cases;
  for (const experiments::PeerCase& c : run_with_progress(o, a, experiments::run_peer_campaign)) {
    const std::string verdict = verdict_name(c.run.verdict);
    cases.push_back({c.source, c.index, c.n, verdict, verdict, c.run.message, c.failed(),
                     c.run.verdict == Verdict::not_installed, c.corpus_file, c.shrunk_points, std::nullopt});
  }
  return report(a, cases, {"dtlab oracle", peer_definition_arguments(a.target)});
}

int run_voronoi_target(const TargetArgs& a) {
  experiments::VoronoiCampaignOptions o;
  o.peers = {a.target};
  set_grid(o, a);
  o.peer_options.timeout_s = 60;
  std::vector<TargetCase> cases;
  for (const experiments::VoronoiCase& c : run_with_progress(o, a, experiments::run_voronoi_campaign)) {
    const std::string verdict = voronoi_verdict_name(c.run.verdict);
    const bool judged = c.not_judged.empty();
    cases.push_back({c.source, c.index, c.n, judged ? verdict : "not-judged", verdict, c.run.message, c.failed(),
                     judged && c.run.verdict == VoronoiVerdict::not_installed, c.corpus_file, c.shrunk_points,
                     c.shrunk_minimal});
  }
  return report(a, cases, {"dtlab voronoi", voronoi_peer_definition_arguments(a.target)});
}

}  // namespace dtlab::cli
