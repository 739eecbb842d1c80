// `dtlab predicates conformance --predicates NAME`: a predicate backend (built-in or
// plugin:PATH.so) against GMP on the hard cases and through whole builds of every
// fuzz family (experiments/conformance.hpp). Exit 0 when it makes no sign error and
// every build is proven Delaunay, 1 otherwise, 2 bad usage.
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/build_options.hpp"
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "experiments/conformance.hpp"

namespace dtlab::cli {

void add_predicates_command(CLI::App& app, int& rc) {
  CLI::App* sub = app.add_subcommand("predicates", "predicate backends: conformance against GMP");
  sub->require_subcommand(1);
  CLI::App* conf = sub->add_subcommand(
      "conformance", "a backend against GMP on hard cases and through whole builds of every fuzz family");
  auto kernel = std::make_shared<KernelArgs>();
  auto o = std::make_shared<experiments::ConformanceOptions>();
  auto json = std::make_shared<bool>(false);
  kernel->add_to(*conf, kPredicatesOption | kEpsOption | kPerturbOption);
  conf->add_option("--cases", o->cases, "cases per predicate and case class")->transform(count_in(1, 1e7))->capture_default_str();
  conf->add_option("--builds", o->builds, "whole builds per fuzz family (0: none)")->transform(count_in(0, 1e6))->capture_default_str();
  conf->add_option("--points", o->points, "points per build")->transform(count_in(4, 1e6))->capture_default_str();
  conf->add_option("--seed", o->seed, "seed of the cases and builds")->capture_default_str();
  conf->add_flag("--json", *json, "print a JSON object on stdout");
  conf->footer("Exit: 0 no sign error and every build valid, 1 otherwise, 2 bad usage.");
  conf->callback([kernel, o, json, &rc] {
    o->predicates = kernel->predicate_spec();
    const experiments::ConformanceReport r = experiments::run_conformance(*o);
    if (*json) std::cout << experiments::to_json(r).dump(2) << "\n";
    else std::cout << experiments::conformance_table(r);
    rc = r.passed() ? kOk : kDefect;
  });
}

}  // namespace dtlab::cli
