#pragma once
// `dtlab predicates conformance`: any predicate backend (built-in or plugin:PATH)
// against GMP on a corpus of hard cases, and through whole builds of every fuzz
// family judged by the exact checker. It reports; it hides nothing: naive and epsilon
// are expected to show sign errors in the exact classes.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "kernel/build.hpp"

namespace dtlab::experiments {

struct ConformanceOptions {
  PredicateSpec predicates;      // the backend under test (perturb: for the builds)
  std::size_t cases = 400;       // per predicate and case class
  std::size_t builds = 8;        // per fuzz family
  std::size_t points = 64;       // per build
  std::uint64_t seed = 1;
};

struct SignTally {
  std::string predicate, case_class;
  std::size_t cases = 0;
  std::size_t flipped = 0;       // +1 for -1 or -1 for +1
  std::size_t false_zero = 0;    // 0 where the exact sign is not
  std::size_t missed_zero = 0;   // a sign where the exact answer is 0
  std::size_t exact_zeros = 0;   // cases whose exact answer is 0
  std::size_t errors() const { return flipped + false_zero + missed_zero; }
};

struct BuildTally {
  std::string family;
  std::size_t builds = 0, valid = 0;  // valid: proven Delaunay (or a lower-dimensional input refused)
  std::map<std::string, std::size_t> failures;  // outcome name -> count
};

struct ConformanceReport {
  std::string backend;
  std::vector<SignTally> signs;
  std::vector<BuildTally> builds;
  std::size_t sign_errors() const;
  std::size_t failed_builds() const;
  bool passed() const { return sign_errors() == 0 && failed_builds() == 0; }
};

ConformanceReport run_conformance(const ConformanceOptions& options);
std::string conformance_table(const ConformanceReport& report);
nlohmann::json to_json(const ConformanceReport& report);

}  // namespace dtlab::experiments
