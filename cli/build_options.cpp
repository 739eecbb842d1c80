#include "cli/build_options.hpp"

#include "cli/number_options.hpp"
#include "options/option_error.hpp"

namespace dtlab::cli {

namespace {

// One of `choices`, with the library's check and message (as CLI::IsMember shows them).
CLI::Validator choice_in(const std::vector<std::string>& choices) {
  return CLI::Validator([&choices](const std::string& s) { return choice_error(s, choices); }, choice_set(choices));
}

}  // namespace

void KernelArgs::add_to(CLI::App& app, unsigned which) {
  if (which & kPredicatesOption)
    app.add_option("--predicates", predicates, "predicate backend: naive, epsilon, adaptive, exact, or plugin:PATH.so")
        ->check(CLI::Validator(predicates_error, "BACKEND"))
        ->capture_default_str();
  if (which & kEpsOption) {
    app.add_option("--eps", eps, "tolerance of the epsilon backend")
        ->check(number_in(0, kMaxEps))
        ->capture_default_str();
    app.add_option("--eps-mode", eps_mode, "epsilon band: absolute or relative to the input magnitudes")
        ->check(choice_in(kEpsModes))
        ->capture_default_str();
  }
  if (which & kPerturbOption)
    app.add_option("--perturb", perturb, "symbolic perturbation of insphere: none or sos")
        ->check(choice_in(kPerturbModes))
        ->capture_default_str();
  if (which & kBoundaryOption)
    app.add_option("--boundary", boundary, "infinite, or bigtet[:FACTOR] (the thesis's enclosing tet)")
        ->capture_default_str();
  if (which & kOrderOption)
    app.add_option("--order", order, "insertion order: input or brio (randomized, Hilbert-sorted rounds)")
        ->check(choice_in(kInsertionOrders))
        ->capture_default_str();
  if (which & kSeedOption)
    app.add_option("--seed", seed, "seed of the insertion order and of the walk")->check(seed_value())->capture_default_str();
  if (which & kThreadsOption)
    threads_option =
        app.add_option("--threads", threads,
                       "threads of the exact check, the file writers and the parallel peers, 0: all; the build "
                       "runs threaded only when --threads is given (with --perturb sos the tets are the same "
                       "for any count)")
            ->transform(count_in(0, 1024))
            ->capture_default_str();
}

BuildOptions KernelArgs::build_options() const {
  try {
    BuildOptions o = KernelOptions::build_options();
    o.threads = build_threads();
    return o;
  } catch (const OptionError& e) {
    throw CLI::ValidationError(e.option(), e.reason());
  }
}

}  // namespace dtlab::cli
