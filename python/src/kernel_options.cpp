#include "python/src/kernel_options.hpp"

namespace dtlab::python {

KernelChoice kernel_choice(const std::string& predicates, const std::string& perturb, const std::string& boundary,
                           const std::string& order, std::uint64_t seed, double eps, const std::string& eps_mode) {
  KernelChoice k;
  k.args = KernelOptions{predicates, eps, eps_mode, perturb, boundary, order, seed};
  k.args.validate();  // OptionError -> ValueError (module.cpp)
  k.predicates = k.args.predicate_spec();
  k.build = k.args.build_options();
  k.build.threads = 1;  // a serial build unless the caller asks for threads (tetrahedralize's threads=)
  return k;
}

}  // namespace dtlab::python
