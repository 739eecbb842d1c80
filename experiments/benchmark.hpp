#pragma once
// `dtlab experiment benchmark`: time and peak memory of dtlab, CGAL and TetGen over
// n = 10^3..10^6 (10^7 with --large) on several distributions, predicate costs per
// backend and the adaptive stage statistics, written as a report folder.
#include <cstdint>
#include <filesystem>
#include <string>

#include "experiments/thesis_failures.hpp"

namespace dtlab::experiments {

struct BenchmarkOptions {
  std::filesystem::path out = "reports/benchmark";
  bool large = false;        // 10^7 uniform, 10^6 for the other distributions
  bool quick = false;        // n <= 10^4 and fewer predicate calls: seconds, says so in the report
  int runs = 3;              // runs per (tool, distribution, n) for n <= 10^5; 1 above
  std::uint64_t seed = 1;
  std::size_t max_n = 0;     // cap on n (0: 10^6, or 10^7 with --large)
  bool figures = true;
  bool progress = false;
  std::string command_line;
};

// Exit code 1 when dtlab gave no answer on some run (a regression); 0 otherwise.
ExperimentResult run_benchmark(const BenchmarkOptions& options);

}  // namespace dtlab::experiments
