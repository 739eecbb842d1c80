#pragma once
// The kernel options shared by every subcommand that builds a tetrahedralization
// (tetra, oracle, bench, voronoi, fuzz): --predicates, --eps, --eps-mode, --perturb,
// --boundary, --order, --seed. One definition, so the names, defaults and help texts
// are the same wherever a DT is built; a command registers the subset that applies.
// The values, their checks and their meaning are the options library's
// (options/kernel_options.hpp, shared with the Python module); this is their CLI form.
#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "options/kernel_options.hpp"

namespace dtlab::cli {

enum KernelOption : unsigned {
  kPredicatesOption = 1u << 0,
  kEpsOption = 1u << 1,        // --eps and --eps-mode
  kPerturbOption = 1u << 2,
  kBoundaryOption = 1u << 3,
  kOrderOption = 1u << 4,
  kSeedOption = 1u << 5,
  kAllKernelOptions = (1u << 6) - 1,
  // --threads: not in kAllKernelOptions (voronoi and fracture have their own), named
  // by the commands that take it: the build, the exact check and the writers
  // (kernel/README.md, "The parallel build").
  kThreadsOption = 1u << 6,
};

struct KernelArgs : KernelOptions {
  unsigned threads = 0;  // 0: all hardware threads
  // The --threads option once registered: the build is threaded only when it was given
  // (on 2 cores the threaded build is not yet faster, kernel/README.md); the exact check
  // and the writers use `threads` either way.
  const CLI::Option* threads_option = nullptr;

  void add_to(CLI::App& app, unsigned which = kAllKernelOptions);
  BuildOptions build_options() const;  // throws CLI::ValidationError on a bad --boundary
  bool threads_given() const { return threads_option && threads_option->count() > 0; }
  unsigned build_threads() const { return threads_given() ? threads : 1; }
};

}  // namespace dtlab::cli
