#pragma once
// Failure reporting of the libFuzzer targets: print what disagreed and the points
// (hex floats, exact), then abort so that libFuzzer saves the input as a crash.
#include <cstdio>
#include <cstdlib>
#include <span>

#include "predicates/point.hpp"

namespace dtlab::fuzz {

[[noreturn]] inline void fuzz_fail(const char* what, std::span<const Point3> pts) {
  std::fprintf(stderr, "dtlab fuzz target: %s\n", what);
  for (const Point3& p : pts) std::fprintf(stderr, "  %a %a %a\n", p.x, p.y, p.z);
  std::abort();
}

}  // namespace dtlab::fuzz
