#pragma once
// The settings of a campaign that change its outcomes, kept in the folder
// (settings.json), so that a resumed run never reports another run's results as its
// own: a run into a folder whose settings differ is refused, naming the setting.
#include <string>

#include <nlohmann/json.hpp>

#include "fuzz/campaign.hpp"

namespace dtlab::fuzz {

// The threads of the campaign's builds, 0 (all hardware threads) resolved: 1 is the
// serial build. Naive and epsilon builds fail differently on different counts.
unsigned build_thread_count(const BuildOptions& build);

// Sets the threads of a campaign's builds (0: all hardware threads), as a campaign and a
// replay of its corpus set them: above 1 (or 0), every case is split across the threads
// however small it is (parallel_grain 1); 1 is the serial build.
void use_build_threads(BuildOptions& build, unsigned threads);

// Keyed by the option that sets each: --seed, --min-points, --points, --predicates
// (the backend labels), --eps, --eps-mode, --boundary, --order, --threads (resolved:
// build_thread_count), --against.
nlohmann::json outcome_settings(const CampaignOptions& options);

// Writes out_dir/settings.json when it is missing; otherwise throws
// std::invalid_argument naming the first setting that differs.
void check_resume_settings(const CampaignOptions& options);

}  // namespace dtlab::fuzz
