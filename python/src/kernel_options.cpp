#include "python/src/kernel_options.hpp"

#include <algorithm>
#include <vector>

namespace dtlab::python {

KernelChoice kernel_choice(const std::string& predicates, const std::string& perturb, const std::string& boundary,
                           const std::string& order, std::uint64_t seed, double eps, const std::string& eps_mode) {
  KernelChoice k;
  CLI::App app{"dtlab", "dtlab"};
  k.args.add_to(app);
  char eps_text[32];
  std::snprintf(eps_text, sizeof eps_text, "%.17g", eps);
  std::vector<std::string> argv = {"--predicates", predicates, "--perturb", perturb, "--boundary", boundary,
                                   "--order",      order,      "--seed",    std::to_string(seed),
                                   "--eps",        eps_text,   "--eps-mode", eps_mode};
  std::reverse(argv.begin(), argv.end());  // CLI11 takes a vector of arguments last-first
  app.parse(argv);                         // CLI::ParseError -> ValueError (module.cpp)
  k.predicates = k.args.predicate_spec();
  k.build = k.args.build_options();
  k.build.threads = 1;  // a serial build unless the caller asks for threads (tetrahedralize's threads=)
  return k;
}

}  // namespace dtlab::python
