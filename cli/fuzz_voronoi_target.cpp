#include "cli/fuzz_voronoi_target.hpp"

#include <cstdio>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/progress.hpp"
#include "experiments/voronoi_campaign.hpp"
#include "voronoi_check/voronoi_peer_command.hpp"

namespace dtlab::cli {

int run_voronoi_target(const VoronoiTargetArgs& a) {
  experiments::VoronoiCampaignOptions o;
  o.peers = {a.target};
  o.sources = experiments::fuzz_family_sources(a.families);
  o.cases = a.only_case ? std::max(a.cases, *a.only_case + 1) : a.cases;
  o.only_case = a.only_case;
  o.min_points = std::min(a.min_points, a.max_points);
  o.max_points = a.max_points;
  o.seed = a.seed;
  o.out_dir = a.out;
  o.shrink = a.shrink;
  o.shrink_budget = a.shrink_budget;
  o.peer_options.timeout_s = 60;
  o.jobs = a.jobs;
  const std::size_t total = a.only_case ? o.sources.size() : o.cases * o.sources.size();
  Progress progress("fuzz", a.quiet);
  std::size_t done = 0, failed = 0;
  o.on_case = [&](const experiments::VoronoiCase& c) {
    failed += c.failed();
    progress.update("cases", ++done, total, std::to_string(failed) + " failing");
  };
  const auto cases = experiments::run_voronoi_campaign(o);
  struct Row {
    std::size_t cases = 0, failing = 0;
    std::map<std::string, std::size_t> verdicts;
  };
  std::map<std::string, Row> rows;
  nlohmann::json failures = nlohmann::json::array();
  std::size_t failing = 0, not_installed = 0;
  for (const auto& c : cases) {
    Row& r = rows[c.source];
    ++r.cases;
    ++r.verdicts[c.not_judged.empty() ? voronoi_verdict_name(c.run.verdict) : "not-judged"];
    not_installed += c.not_judged.empty() && c.run.verdict == VoronoiVerdict::not_installed;
    if (!c.failed()) continue;
    ++r.failing, ++failing;
    failures.push_back({{"source", c.source},
                        {"case", c.index},
                        {"n", c.n},
                        {"verdict", voronoi_verdict_name(c.run.verdict)},
                        {"message", c.run.message},
                        {"corpus_file", c.corpus_file},
                        {"shrunk_points", c.shrunk_points},
                        {"minimal", c.shrunk_minimal}});
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
    std::printf("%-18s %6s %8s  %s\n", "family", "cases", "failing", "verdicts");
    for (const auto& [src, r] : rows) {
      std::string v;
      for (const auto& [name, k] : r.verdicts) v += (v.empty() ? "" : ", ") + name + " " + std::to_string(k);
      std::printf("%-18s %6zu %8zu  %s\n", src.c_str(), r.cases, r.failing, v.c_str());
    }
    for (const auto& f : failures)
      if (!f["corpus_file"].get<std::string>().empty())
        std::printf("  %s case %zu: %s, shrunk to %zu points%s: %s/%s (dtlab voronoi %s/%s --against %s%s)\n",
                    f["source"].get<std::string>().c_str(), f["case"].get<std::size_t>(),
                    f["verdict"].get<std::string>().c_str(), f["shrunk_points"].get<std::size_t>(),
                    f["minimal"].get<bool>() ? " (1-minimal)" : "", a.out.c_str(),
                    f["corpus_file"].get<std::string>().c_str(), a.out.c_str(),
                    f["corpus_file"].get<std::string>().c_str(), a.target.c_str(),
                    voronoi_peer_definition_arguments(a.target).c_str());
    std::printf("%s: %zu cases, %zu failing%s\n", a.target.c_str(), cases.size(), failing,
                not_installed ? " (not installed)" : "");
  }
  if (not_installed == cases.size() && !cases.empty()) return 3;
  return failing ? kDefect : kOk;
}

}  // namespace dtlab::cli
