#pragma once
// A fuzz campaign: families x cases x backends, each case built, checked exactly,
// classified, and (when it fails) shrunk into the corpus. Results are JSON lines,
// one per (case, backend), so a campaign can be resumed and its shards merged.
//
// Determinism: case i of family F in a campaign with seed S always has the seed
// case_seed(S, F, i) and the same points, whatever --jobs and --shard are; only
// the timings and the order of the JSON lines vary between runs.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/oracle_hook.hpp"
#include "fuzz/outcome.hpp"
#include "kernel/build.hpp"

namespace dtlab::fuzz {

struct CampaignOptions {
  std::vector<std::string> families;           // registry names (fuzz/families.hpp)
  std::size_t cases = 100;                     // per family
  std::optional<std::size_t> only_case;        // run just this case index
  std::size_t min_points = 8, max_points = 64; // n per case, drawn from the case seed
  std::uint64_t seed = 1;
  std::vector<PredicateSpec> backends;
  BuildOptions build;                          // boundary; the seed is set per case
  std::vector<OracleHook> oracles;
  unsigned jobs = 1;
  std::string out_dir;
  unsigned shard = 0, shards = 1;              // this run does cases with ordinal % shards == shard
  bool shrink = true;
  std::size_t shrink_budget = 500;             // predicate calls per failing case
  // Called after each case (all its backends), under a lock: done, total, failing.
  std::function<void(std::size_t, std::size_t, std::size_t)> progress;
};

struct CaseRecord {
  std::string id;  // "<family>-s<seed>-<index>"
  std::string family;
  std::size_t index = 0;
  std::uint64_t campaign_seed = 0, case_seed = 0;
  std::size_t points = 0;
  std::string backend;  // backend_label()
  std::string predicates;
  bool perturb = false;
  std::string boundary;  // "infinite" or "bigtet:FACTOR"
  unsigned threads = 0;  // the build's threads (build_thread_count); 0: a line that does not say
  CaseRun run;
  std::size_t shrunk_points = 0;  // 0: not shrunk
  std::string corpus_file;        // relative to the campaign folder
  std::string version, commit;    // the dtlab build that produced it (dtlab/build_info.hpp)
};

struct CampaignResult {
  std::vector<CaseRecord> records;  // every record in the folder: resumed ones too
  std::size_t ran = 0, resumed = 0;
  std::size_t failing() const;
};

std::string boundary_label(const BuildOptions& options);
std::string order_label(const BuildOptions& options);  // "brio" or "input", as --order takes it
std::string case_id(const std::string& family, std::uint64_t seed, std::size_t index);
std::size_t case_points(std::uint64_t case_seed, std::size_t min_points, std::size_t max_points);

// Runs the campaign; creates out_dir (and out_dir/corpus) as needed; throws
// std::runtime_error when the folder cannot be written.
CampaignResult run_campaign(const CampaignOptions& options);

// Every record in the JSON-lines files (results*.jsonl) of a campaign folder;
// lines that do not parse (a run killed mid-write) are skipped.
std::vector<CaseRecord> read_records(const std::string& out_dir);

// A campaign's results file by its name: results*.jsonl (one per shard).
bool is_results_file(const std::string& file_name);

}  // namespace dtlab::fuzz
