#pragma once
// What an insertion loop (serial or parallel) reports to build_with, in insertion ranks
// (vertex ids): build_with translates it to input indices once the loop is done.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kernel/build.hpp"

namespace dtlab {

struct InsertionLog {
  struct Failure {
    std::uint32_t rank;  // the point being inserted
    FailureKind kind;
    std::string detail;
  };
  // (a point not inserted, the vertex equal to it), in no particular order.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicates;
  std::optional<Failure> failure;
  std::vector<std::uint32_t> skipped;  // not inserted because of the failure (the failing point too)
};

}  // namespace dtlab
