#pragma once
// The summary of one build as JSON: `dtlab tetra --json` and the Python module's
// Tetrahedralization.stats.
#include <nlohmann/json.hpp>

#include "kernel/build.hpp"
#include "options/kernel_options.hpp"

namespace dtlab {

nlohmann::json tetra_summary(const BuildResult& r, const KernelOptions& k);

}  // namespace dtlab
