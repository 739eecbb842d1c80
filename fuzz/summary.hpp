#pragma once
// The campaign summary: family x backend -> outcome counts.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz/campaign.hpp"

namespace dtlab::fuzz {

struct SummaryCell {
  std::size_t cases = 0, ok = 0;
  std::map<std::string, std::size_t> outcomes;
  double build_seconds = 0;
};

// Keyed by (family, backend label + boundary when not "infinite").
using Summary = std::map<std::pair<std::string, std::string>, SummaryCell>;

Summary summarize(const std::vector<CaseRecord>& records);

// A Markdown table: family | backend | cases | ok | outcomes (non-valid counts) | ms/case.
std::string summary_table(const Summary& s);

nlohmann::json summary_json(const Summary& s);

}  // namespace dtlab::fuzz
