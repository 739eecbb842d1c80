#pragma once
// The kernel options of the Python API (predicates, perturb, boundary, order, seed, eps,
// eps_mode), validated by the CLI's own option definitions (cli/build_options.hpp), so
// a bad value raises ValueError with the message `dtlab tetra` prints for it.
#include <cstdint>
#include <string>

#include "cli/build_options.hpp"

namespace dtlab::python {

struct KernelChoice {
  cli::KernelArgs args;
  PredicateSpec predicates;
  BuildOptions build;
};

KernelChoice kernel_choice(const std::string& predicates, const std::string& perturb, const std::string& boundary,
                           const std::string& order, std::uint64_t seed, double eps, const std::string& eps_mode);

}  // namespace dtlab::python
