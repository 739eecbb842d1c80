#pragma once
// The hard predicate cases of the conformance suite, by class. Every class is built
// from exactly representable configurations (small integers, powers of two), so the
// exact answer is known to be 0 where the class says "exactly".
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::experiments {

struct PredicateCases {
  std::string case_class;
  std::vector<std::array<Point3, 4>> orient;  // orient3d(a, b, c, d)
  std::vector<std::array<Point3, 5>> insphere;  // insphere(a, b, c, d, e)
};

// random, near-degenerate, exactly degenerate, ulp-nudged (the adaptive stages'
// boundaries), Kettner's grid, and the degenerate classes scaled by 2^500 and 2^-500.
std::vector<PredicateCases> conformance_cases(std::size_t per_class, std::uint64_t seed);

}  // namespace dtlab::experiments
