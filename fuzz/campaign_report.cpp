#include "fuzz/campaign_report.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

#include "fuzz/campaign_settings.hpp"
#include "fuzz/run_environment.hpp"
#include "kernel/output_file.hpp"

namespace dtlab::fuzz {

namespace fs = std::filesystem;

namespace {

void write_file(const fs::path& file, const std::string& text) {
  write_text_file(file.string(), text);
}

nlohmann::json campaign_settings(const CampaignOptions& o) {
  nlohmann::json backends = nlohmann::json::array(), oracles = nlohmann::json::array();
  for (const auto& b : o.backends) {
    nlohmann::json j = {{"label", backend_label(b)}, {"predicates", b.backend}, {"perturb", b.perturb ? "sos" : "none"}};
    if (b.backend == "epsilon") {
      j["eps"] = b.eps;
      j["relative_eps"] = b.relative_eps;
    }
    backends.push_back(j);
  }
  for (const auto& h : o.oracles) oracles.push_back(h.name);
  nlohmann::json j = {{"seed", o.seed},
                      {"case_seeds",
                       "case_seed(seed, family, index): SplitMix64 of the seed, FNV-1a of family and index; "
                       "each results line has its case_seed"},
                      {"families", o.families},
                      {"cases_per_family", o.cases},
                      {"min_points", o.min_points},
                      {"max_points", o.max_points},
                      {"backends", backends},
                      {"boundary", boundary_label(o.build)},
                      {"order", order_label(o.build)},
                      {"threads", build_thread_count(o.build)},
                      {"oracles", oracles},
                      {"jobs", o.jobs},
                      {"shard", o.shard},
                      {"shards", o.shards},
                      {"shrink", o.shrink},
                      {"shrink_budget", o.shrink_budget}};
  if (o.only_case) j["only_case"] = *o.only_case;
  return j;
}

}  // namespace

void write_campaign_environment(const CampaignOptions& o) {
  const std::string name = o.shards > 1 ? "environment.shard-" + std::to_string(o.shard) + "-of-" +
                                              std::to_string(o.shards) + ".json"
                                        : "environment.json";
  const fs::path file = fs::path(o.out_dir) / name;
  nlohmann::json runs = nlohmann::json::array();
  if (std::ifstream in(file); in) {
    try {
      const auto old = nlohmann::json::parse(in);
      if (old.contains("runs") && old["runs"].is_array()) runs = old["runs"];
    } catch (const nlohmann::json::exception&) {
      // a file cut by a kill: start the list again
    }
  }
  nlohmann::json run = run_environment();
  run["campaign"] = campaign_settings(o);
  runs.push_back(std::move(run));
  write_file(file, nlohmann::json{{"runs", runs}}.dump(2) + "\n");
}

void write_summary_files(const std::string& dir, const Summary& summary) {
  write_file(fs::path(dir) / "summary.md", summary_markdown(summary));
  write_file(fs::path(dir) / "summary.json", summary_json(summary, false).dump(2) + "\n");
}

std::vector<CaseRecord> read_campaigns(const std::vector<std::string>& dirs) {
  std::vector<CaseRecord> all;
  std::set<std::string> seen;
  for (const auto& dir : dirs)
    for (auto& r : read_records(dir))
      if (seen.insert(r.id + "|" + r.backend + "|" + r.boundary).second) all.push_back(std::move(r));
  return all;
}

nlohmann::json read_environments(const std::vector<std::string>& dirs) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& dir : dirs) {
    if (!fs::is_directory(dir)) continue;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      if (e.is_regular_file() && name.rfind("environment", 0) == 0 && e.path().extension() == ".json")
        files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      std::ifstream in(f);
      try {
        out.push_back({{"folder", dir}, {"file", f.filename().string()}, {"runs", nlohmann::json::parse(in).value("runs", nlohmann::json::array())}});
      } catch (const nlohmann::json::exception&) {
      }
    }
  }
  return out;
}

}  // namespace dtlab::fuzz
