#pragma once
// One fuzz case under one backend: build, exact check, optional oracles, and the
// classification into a single outcome name.
//
// Outcomes: "valid"; "lower-dimensional" (the input really is flat or collinear,
// proven exactly, and the build said so); a build failure's name (walk-cycle,
// flip-stuck, inconsistent-adjacency, outside-boundary); "false-lower-dimensional"
// (a 3D input rejected as flat); the first defect the checker found, in the order
// of DefectKind (broken-adjacency, inverted, ...); "oracle-<name>" when our result
// is valid but an oracle disagrees; "exception" when the build threw.
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "fuzz/oracle_hook.hpp"
#include "kernel/build.hpp"

namespace dtlab::fuzz {

// "adaptive+sos", "naive", "epsilon" ...: the column name in the summary table.
std::string backend_label(const PredicateSpec& spec);

struct CaseRun {
  std::string outcome;
  std::map<std::string, std::uint64_t> defects;  // every defect kind with its count
  std::string detail;                            // first witness or failure detail
  std::vector<std::uint32_t> witness_tets, witness_vertices;  // the first witness's tets and input points
  std::uint64_t tets = 0, duplicates = 0;
  std::uint64_t parallel_passes = 0;  // insertion passes the build ran on threads (0: all serial)
  double build_seconds = 0, check_seconds = 0;
  bool ok() const { return outcome == "valid" || outcome == "lower-dimensional"; }
};

CaseRun run_case(std::span<const Point3> points, const PredicateSpec& predicates,
                 const BuildOptions& options, const std::vector<OracleHook>& oracles = {});

// Exactly: fewer than four distinct points, or all of them on one plane.
bool is_lower_dimensional(std::span<const Point3> points);

}  // namespace dtlab::fuzz
