#pragma once
// The kernel options every caller that builds a tetrahedralization shares (the CLI's
// tetra, oracle, bench, voronoi, fuzz and the Python module): predicates, eps,
// eps_mode, perturb, boundary, order, seed, as plain values. One definition of their
// defaults, their checks and their meaning as PredicateSpec + BuildOptions; the CLI
// registers them as options (cli/build_options.hpp), Python passes them as arguments.
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/build.hpp"

namespace dtlab {

struct KernelOptions {
  std::string predicates = "adaptive";
  double eps = 1e-12;
  std::string eps_mode = "absolute";
  std::string perturb = "sos";
  std::string boundary = "infinite";
  std::string order = "brio";
  std::uint64_t seed = 1;

  PredicateSpec predicate_spec() const;
  BuildOptions build_options() const;  // throws OptionError on a bad --boundary
  // Every value checked, in the order predicates, perturb, order, eps, eps_mode,
  // boundary; the first bad one throws OptionError.
  void validate() const;
};

// The choices of the options that take one word.
inline const std::vector<std::string> kEpsModes = {"absolute", "relative"};
inline const std::vector<std::string> kPerturbModes = {"none", "sos"};
inline const std::vector<std::string> kInsertionOrders = {"input", "brio"};
inline constexpr double kMaxEps = 1e300;

// "" when `name` is a backend (a built-in name, or plugin:PATH of a loadable plug-in),
// else why not.
std::string predicates_error(const std::string& name);
// "" when `value` is one of `choices`, else "VALUE not in {a,b}".
std::string choice_error(const std::string& value, const std::vector<std::string>& choices);
// "{a,b}", as a choice's help shows it.
std::string choice_set(const std::vector<std::string>& choices);

}  // namespace dtlab
