#pragma once
// The kernel options of the Python API (predicates, perturb, boundary, order, seed, eps,
// eps_mode), checked by the options library the CLI uses too (options/kernel_options.hpp),
// so a bad value raises ValueError with the message `dtlab tetra` prints for it.
#include <cstdint>
#include <string>

#include "options/kernel_options.hpp"

namespace dtlab::python {

struct KernelChoice {
  KernelOptions args;
  PredicateSpec predicates;
  BuildOptions build;
};

KernelChoice kernel_choice(const std::string& predicates, const std::string& perturb, const std::string& boundary,
                           const std::string& order, std::uint64_t seed, double eps, const std::string& eps_mode);

}  // namespace dtlab::python
