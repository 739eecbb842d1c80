#include "fuzz/campaign_settings.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "kernel/output_file.hpp"

namespace dtlab::fuzz {

namespace fs = std::filesystem;

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
          {"--order", o.build.order == InsertionOrder::brio ? "brio" : "input"},
          {"--against", against}};
}

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
