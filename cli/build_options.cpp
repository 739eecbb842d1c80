#include "cli/build_options.hpp"

#include "cli/number_options.hpp"
#include "predicates/backend_choice.hpp"

namespace dtlab::cli {

std::string predicates_error(const std::string& name) {
  for (std::string_view b : kBackendNames)
    if (name == b) return "";
  if (name.rfind(kPluginPrefix, 0) != 0) {
    std::string list;
    for (std::string_view b : kBackendNames) list += (list.empty() ? "" : ",") + std::string(b);
    return name + " not in {" + list + "} and not plugin:PATH.so";
  }
  try {
    load_plugin(name.substr(kPluginPrefix.size()));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

void KernelArgs::add_to(CLI::App& app, unsigned which) {
  if (which & kPredicatesOption)
    app.add_option("--predicates", predicates, "predicate backend: naive, epsilon, adaptive, exact, or plugin:PATH.so")
        ->check(CLI::Validator(predicates_error, "BACKEND"))
        ->capture_default_str();
  if (which & kEpsOption) {
    app.add_option("--eps", eps, "tolerance of the epsilon backend")->check(number_in(0, 1e300))->capture_default_str();
    app.add_option("--eps-mode", eps_mode, "epsilon band: absolute or relative to the input magnitudes")
        ->check(CLI::IsMember({"absolute", "relative"}))
        ->capture_default_str();
  }
  if (which & kPerturbOption)
    app.add_option("--perturb", perturb, "symbolic perturbation of insphere: none or sos")
        ->check(CLI::IsMember({"none", "sos"}))
        ->capture_default_str();
  if (which & kBoundaryOption)
    app.add_option("--boundary", boundary, "infinite, or bigtet[:FACTOR] (the thesis's enclosing tet)")
        ->capture_default_str();
  if (which & kOrderOption)
    app.add_option("--order", order, "insertion order: input or brio (randomized, Hilbert-sorted rounds)")
        ->check(CLI::IsMember({"input", "brio"}))
        ->capture_default_str();
  if (which & kSeedOption)
    app.add_option("--seed", seed, "seed of the insertion order and of the walk")->check(seed_value())->capture_default_str();
  if (which & kThreadsOption)
    app.add_option("--threads", threads,
                   "threads of the build, the exact check, the file writers and the parallel peers, 0: all (with --perturb sos the tets are the same for any count)")
        ->transform(count_in(0, 1024))
        ->capture_default_str();
}

PredicateSpec KernelArgs::predicate_spec() const {
  return PredicateSpec{predicates, eps, eps_mode == "relative", perturb == "sos"};
}

BuildOptions KernelArgs::build_options() const {
  BuildOptions o;
  o.order = order == "input" ? InsertionOrder::input : InsertionOrder::brio;
  o.seed = seed;
  o.threads = threads;
  if (boundary == "infinite") {
    o.boundary = Boundary::infinite;
  } else if (boundary.rfind("bigtet", 0) == 0) {
    o.boundary = Boundary::bigtet;
    if (boundary.size() > 6) {
      if (boundary[6] != ':') throw CLI::ValidationError("--boundary", "expected bigtet[:FACTOR]");
      // FACTOR 1 is the smallest tet holding the bounding box: less cannot hold the points.
      const std::string why = number_options_detail::check_number(boundary.substr(7), 1, 1e300, false);
      if (!why.empty()) throw CLI::ValidationError("--boundary", "bigtet FACTOR " + why);
      o.bigtet_factor = std::stod(boundary.substr(7));
    }
  } else {
    throw CLI::ValidationError("--boundary", "expected infinite or bigtet[:FACTOR], got '" + boundary + "'");
  }
  return o;
}

}  // namespace dtlab::cli
