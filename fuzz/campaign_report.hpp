#pragma once
// The files of a campaign folder besides results*.jsonl and corpus/:
//   environment.json (environment.shard-K-of-N.json for a shard): one entry per run
//     into the folder (a resumed campaign has several): build, machine, command line,
//     date, and the campaign's settings and seed;
//   summary.md and summary.json: the summary of every result in the folder (no
//     timings, so a merged sharded campaign gives the same files as an unsharded one).
#include <string>
#include <vector>

#include "fuzz/campaign.hpp"
#include "fuzz/summary.hpp"

namespace dtlab::fuzz {

void write_campaign_environment(const CampaignOptions& options);
void write_summary_files(const std::string& dir, const Summary& summary);

// The records of several campaign folders (shards run on different machines), each
// (case, backend, boundary) once: a shard copied twice is not counted twice.
std::vector<CaseRecord> read_campaigns(const std::vector<std::string>& dirs);

// Every environment*.json of the folders, as {"folder": ..., "file": ..., "runs": [...]}.
nlohmann::json read_environments(const std::vector<std::string>& dirs);

}  // namespace dtlab::fuzz
