#pragma once
// The corpus of shrunk failing inputs: <dir>/corpus/<name>.node with a sidecar
// <name>.json holding the backend, boundary, case seed, outcome and the commands
// that reproduce it. Replaying a corpus re-runs every entry.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/campaign.hpp"

namespace dtlab::fuzz {

struct CorpusEntryInfo {
  std::string original_command;  // regenerates the unshrunk case
  std::size_t shrink_tests = 0;
  bool minimal = false;
  std::string order = "brio";  // the build's insertion order (order_label): the sidecar's "order"
  // The epsilon backend's band (the sidecar's "eps", "eps_mode"; other backends: none).
  double eps = 0;
  bool relative_eps = false;
  std::vector<std::string> against;  // the oracles' names (OracleHook::name): the sidecar's "against"
};

// <out_dir>/corpus/<name>.node and .json of a record (its case, backend and boundary):
// the files write_corpus_entry writes for it.
std::vector<std::string> corpus_entry_files(const std::string& out_dir, const CaseRecord& record);

// Writes <out_dir>/corpus/<name>.node and .json; returns "corpus/<name>.node".
std::string write_corpus_entry(const std::string& out_dir, const CaseRecord& record,
                               const std::vector<Point3>& points, const CorpusEntryInfo& info);

struct ReplayResult {
  std::string file;
  std::string recorded_outcome;  // from the sidecar, "" without one
  std::string backend;
  std::string boundary;
  unsigned threads = 1;  // the build's threads (1: serial), as --threads takes it
  std::string order;     // "brio" or "input", as --order takes it
  std::vector<std::string> against;  // the oracles this run compared with
  CaseRun run;
};

// The hooks for oracle names (a sidecar's "against"), for the entry's backend and build:
// the CLI builds them from oracle/, as it does for a campaign. Throws
// std::invalid_argument for a name it has no oracle for (replay_corpus reports it as the
// sidecar's error, with the line of "against").
using OracleFactory = std::function<std::vector<OracleHook>(const std::vector<std::string>& names,
                                                            const PredicateSpec& spec, const BuildOptions& build)>;

struct ReplayOptions {
  std::vector<PredicateSpec> backends;      // empty: each entry's recorded backend
  std::optional<BuildOptions> boundary;     // nullopt: each entry's recorded boundary (only
                                            // its boundary and bigtet factor are used)
  std::optional<unsigned> threads;          // nullopt: each entry's recorded threads; 0: all
  std::optional<InsertionOrder> order;      // nullopt: each entry's recorded order
  std::optional<std::vector<std::string>> against;  // nullopt: each entry's recorded oracles
  OracleFactory oracles;                            // needed when an entry is compared with oracles
};

// `path`: a .node file, a corpus folder, or a campaign folder (its corpus/ is used).
// Files are replayed in name order, each built as its campaign built it: the sidecar's
// backend, boundary, case seed, order, threads (use_build_threads; a sidecar without
// "order" or "threads", written before they were kept: brio and serial) and the oracles it
// was compared with ("against", through `options.oracles`; none in older sidecars), so an
// entry that differed from an oracle fails again as recorded. Throws
// InputError for unreadable input, naming the file (and the line of a bad field).
std::vector<ReplayResult> replay_corpus(const std::string& path, const ReplayOptions& options);

// "infinite", "bigtet" or "bigtet:FACTOR" into `options`; false when malformed.
bool parse_boundary(const std::string& text, BuildOptions& options);

}  // namespace dtlab::fuzz
