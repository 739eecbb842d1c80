#pragma once
// The sections of the thesis-failures experiment. Each runs its measurements,
// writes its raw data under DIR/data and returns what the report needs.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/csv_writer.hpp"
#include "kernel/build.hpp"

namespace dtlab::experiments {

struct SectionContext {
  std::filesystem::path dir;  // the report folder
  bool quick = false;
  std::uint64_t seed = 1;
  std::vector<PredicateSpec> extra_backends;  // rows after the built-in ones (a plug-in, ...)
};

// A reproducible per-case seed from the experiment seed and what the case is.
std::uint64_t case_seed(std::uint64_t seed, const std::string& what, std::uint64_t n, std::uint64_t index);

// Failure rate per backend x family x n (data/rates.csv).
nlohmann::json rates_section(const SectionContext& c);
// The epsilon "fix": failure rate vs eps, absolute and relative (data/epsilon.csv).
nlohmann::json epsilon_section(const SectionContext& c);
// The big enclosing tetrahedron: missing hull tets vs factor (data/bigtet.csv).
nlohmann::json bigtet_section(const SectionContext& c);
// Cost of the robust backends and the adaptive stages (data/cost.csv).
nlohmann::json cost_section(const SectionContext& c);
// Ray-intersection vs SDF vs winding sampling on the torus with holes (data/sampling.csv).
nlohmann::json sampling_section(const SectionContext& c);
// One small naive failure with overlapping / inverted tets, shrunk (data/overlap_case.json).
nlohmann::json overlap_case_section(const SectionContext& c);

}  // namespace dtlab::experiments
