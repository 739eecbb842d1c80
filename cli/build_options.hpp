#pragma once
// The kernel options shared by every subcommand that builds a tetrahedralization
// (tetra, oracle, fuzz, voronoi, ...): --predicates, --eps, --eps-mode, --perturb,
// --boundary, --order, --seed.
#include <string>

#include <CLI/CLI.hpp>

#include "kernel/build.hpp"

namespace dtlab::cli {

struct KernelArgs {
  std::string predicates = "adaptive";
  double eps = 1e-12;
  std::string eps_mode = "absolute";
  std::string perturb = "sos";
  std::string boundary = "infinite";
  std::string order = "brio";
  std::uint64_t seed = 1;

  void add_to(CLI::App& app);
  PredicateSpec predicate_spec() const;
  BuildOptions build_options() const;  // throws CLI::ValidationError on a bad --boundary
};

}  // namespace dtlab::cli
