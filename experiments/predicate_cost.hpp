#pragma once
// Cost of one predicate call per backend, on random tuples of general-position
// points and of points one ulp away from exact degeneracies.
#include <cstdint>

#include <nlohmann/json.hpp>

namespace dtlab::experiments {

// Rows {points, backend, predicate, calls, ns_per_call, zeros, stages (adaptive)}.
nlohmann::json measure_predicate_costs(std::size_t calls, std::uint64_t seed);

}  // namespace dtlab::experiments
