#include "fuzz/campaign_settings.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "kernel/output_file.hpp"
#include "kernel/parallel_for.hpp"

namespace dtlab::fuzz {

namespace fs = std::filesystem;

unsigned build_thread_count(const BuildOptions& build) { return thread_count(build.threads); }

void use_build_threads(BuildOptions& build, unsigned threads) {
  build.threads = threads;
  if (threads != 1) build.parallel_grain = 1;
}

nlohmann::json outcome_settings(const CampaignOptions& o) {
  nlohmann::json labels = nlohmann::json::array(), against = nlohmann::json::array();
  nlohmann::json eps = nullptr, eps_mode = nullptr;
  for (const auto& b : o.backends) {
    labels.push_back(backend_label(b));
    if (b.backend == "epsilon") {
      eps = b.eps;
      eps_mode = b.relative_eps ? "relative" : "absolute";
    }
  }
  for (const auto& h : o.oracles) against.push_back(h.name);
  return {{"--seed", o.seed},
          {"--min-points", o.min_points},
          {"--points", o.max_points},
          {"--predicates", labels},
          {"--eps", eps},
          {"--eps-mode", eps_mode},
          {"--boundary", boundary_label(o.build)},
          {"--order", order_label(o.build)},
          {"--threads", build_thread_count(o.build)},
          {"--against", against}};
}

namespace {

// The first results*.jsonl of `dir` holding any record ("" if none).
std::string results_without_settings(const std::string& dir) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (is_results_file(name) && e.is_regular_file(ec) && e.file_size(ec) > 0) return name;
  }
  return "";
}

}  // namespace

void check_resume_settings(const CampaignOptions& o) {
  const fs::path file = fs::path(o.out_dir) / "settings.json";
  const nlohmann::json now = outcome_settings(o);
  nlohmann::json old;
  if (std::ifstream in(file); in) {
    try {
      old = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception&) {
      throw std::invalid_argument(file.string() + " cannot be read: not resuming into " + o.out_dir);
    }
  }
  if (old.is_null()) {
    if (const std::string kept = results_without_settings(o.out_dir); !kept.empty())
      throw std::invalid_argument(
          "--out " + o.out_dir + " holds results (" + kept +
          ") but no settings.json (removed, or written before dtlab kept one): the "
          "settings of those outcomes are unknown, so they are not resumed (use another --out)");
    write_text_file(file.string(), now.dump(2) + "\n");
    return;
  }
  for (const auto& [key, value] : now.items())
    if (!old.contains(key) || old[key] != value)
      throw std::invalid_argument("--out " + o.out_dir + " holds a campaign run with " + key + " " +
                                  (old.contains(key) ? old[key].dump() : std::string("unset")) + ", this run has " +
                                  value.dump() + ": its results would not be this run's (use another --out)");
}

}  // namespace dtlab::fuzz
