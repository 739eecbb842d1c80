#pragma once
// The summary of one build, as text and as JSON.
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/build_options.hpp"
#include "kernel/build.hpp"

namespace dtlab::cli {

nlohmann::json tetra_summary(const BuildResult& r, const KernelArgs& k);
void print_tetra_summary(std::FILE* out, const BuildResult& r, const std::string& input);

}  // namespace dtlab::cli
