#pragma once
// The summary of one build as text (its JSON form: options/tetra_summary.hpp).
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/build_options.hpp"
#include "kernel/build.hpp"
#include "options/tetra_summary.hpp"  // tetra_summary: the JSON form
#include "oracle/check/check.hpp"

namespace dtlab::cli {

void print_tetra_summary(std::FILE* out, const BuildResult& r, const std::string& input);
// `tetra --check`: the verdict, the defect counts per kind and a few witnesses.
void print_tetra_check(std::FILE* out, const CheckReport& r);

}  // namespace dtlab::cli
