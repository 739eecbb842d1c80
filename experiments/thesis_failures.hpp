#pragma once
// `dtlab experiment thesis-failures`: reproduces, measures and explains the failures of
// the thesis's chapter 5 and writes a self-contained report folder.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dtlab::experiments {

struct ThesisFailuresOptions {
  std::filesystem::path out = "reports/thesis-failures";
  bool quick = false;        // fewer sizes and cases: seconds instead of minutes
  std::uint64_t seed = 1;
  bool figures = true;       // run the matplotlib script
  bool progress = false;     // one line per section on stderr
  std::string command_line;  // recorded in the report
  std::vector<std::string> extra_predicates;  // more rows of the failure-rate table (plugin:PATH, ...), no sos
};

struct ExperimentResult {
  int exit_code = 0;         // 0 ok; 1 a robust backend showed a defect (a regression)
  nlohmann::json facts;      // the headline numbers (also in DIR/data/facts.json)
};

ExperimentResult run_thesis_failures(const ThesisFailuresOptions& options);

}  // namespace dtlab::experiments
