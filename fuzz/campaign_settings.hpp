#pragma once
// The settings of a campaign that change its outcomes, kept in the folder
// (settings.json), so that a resumed run never reports another run's results as its
// own: a run into a folder whose settings differ is refused, naming the setting.
#include <string>

#include <nlohmann/json.hpp>

#include "fuzz/campaign.hpp"

namespace dtlab::fuzz {

// Keyed by the option that sets each: --seed, --min-points, --points, --predicates
// (the backend labels), --eps, --eps-mode, --boundary, --order, --against.
nlohmann::json outcome_settings(const CampaignOptions& options);

// Writes out_dir/settings.json when it is missing; otherwise throws
// std::invalid_argument naming the first setting that differs.
void check_resume_settings(const CampaignOptions& options);

}  // namespace dtlab::fuzz
