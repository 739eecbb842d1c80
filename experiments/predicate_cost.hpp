#pragma once
// Cost of one predicate call per backend on two kinds of tuples: `uniform` (random
// points in general position, where every filter succeeds) and `near_degenerate`
// (each orient3d tuple has its 4th point rounded from the plane of the first three,
// each insphere tuple has 5 points rounded from one sphere: the exact determinant is
// within the rounding error, so a float filter cannot decide it). For adaptive the
// share of calls each stage decided is measured too: it shows whether the input is
// really hard for the filter.
#include <cstdint>

#include <nlohmann/json.hpp>

namespace dtlab::experiments {

// Rows {points, backend, predicate, calls, ns_per_call, zeros, stages (adaptive)}.
nlohmann::json measure_predicate_costs(std::size_t calls, std::uint64_t seed);

}  // namespace dtlab::experiments
