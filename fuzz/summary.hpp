#pragma once
// The campaign summary: family x backend -> cases, failures, failure rate with its
// 95% (Wilson) interval, and the kinds of failure. Everything but the timing column
// of the terminal table depends only on the records, not on their order, --jobs or
// --shard: a merged sharded campaign has the same summary as an unsharded one.
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz/campaign.hpp"
#include "fuzz/rate_interval.hpp"

namespace dtlab::fuzz {

struct SummaryCell {
  std::size_t cases = 0, ok = 0;
  std::map<std::string, std::size_t> outcomes;  // every outcome, ok ones too
  double build_seconds = 0;
  std::size_t failures() const { return cases - ok; }
  RateInterval failure_rate() const { return wilson_interval(failures(), cases); }
  std::map<std::string, std::size_t> failure_kinds() const;  // the outcomes that are not ok
};

struct Summary {
  // Keyed by (family, backend label + boundary when not "infinite").
  std::map<std::pair<std::string, std::string>, SummaryCell> cells;
  std::set<std::string> builds;  // "VERSION COMMIT" of every record ("unknown" when a line has none)
  std::size_t cases() const;
  std::size_t failures() const;
};

Summary summarize(const std::vector<CaseRecord>& records);

// A Markdown table: family | backend | cases | failures | failure rate [95% CI] |
// kinds of failure | outcomes, and ms/case when `with_timing`.
std::string summary_table(const Summary& s, bool with_timing = true);

// summary.md: a title, the builds, the table without timings, and how to read it.
std::string summary_markdown(const Summary& s);

// Per cell: family, backend, cases, failures, rate, ci95 [low, high], failure_kinds,
// outcomes (and build_s when `with_timing`); totals and the builds.
nlohmann::json summary_json(const Summary& s, bool with_timing = true);

}  // namespace dtlab::fuzz
