#include "options/kernel_options.hpp"

#include <cstdio>

#include "options/number_check.hpp"
#include "options/option_error.hpp"
#include "predicates/backend_choice.hpp"

namespace dtlab {

std::string choice_set(const std::vector<std::string>& choices) {
  std::string s = "{";
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (i) s += ',';
    s += choices[i];
  }
  return s + "}";
}

std::string choice_error(const std::string& value, const std::vector<std::string>& choices) {
  for (const auto& c : choices)
    if (value == c) return "";
  return value + " not in " + choice_set(choices);
}

std::string predicates_error(const std::string& name) {
  for (std::string_view b : kBackendNames)
    if (name == b) return "";
  if (name.rfind(kPluginPrefix, 0) != 0) {
    std::string list;
    for (std::string_view b : kBackendNames) {
      if (!list.empty()) list += ',';  // (not "," + string: GCC 12's -Wrestrict false positive)
      list += b;
    }
    return name + " not in {" + list + "} and not plugin:PATH.so";
  }
  try {
    load_plugin(name.substr(kPluginPrefix.size()));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

PredicateSpec KernelOptions::predicate_spec() const {
  return PredicateSpec{predicates, eps, eps_mode == "relative", perturb == "sos"};
}

BuildOptions KernelOptions::build_options() const {
  BuildOptions o;
  o.order = order == "input" ? InsertionOrder::input : InsertionOrder::brio;
  o.seed = seed;
  if (boundary == "infinite") {
    o.boundary = Boundary::infinite;
  } else if (boundary.rfind("bigtet", 0) == 0) {
    o.boundary = Boundary::bigtet;
    if (boundary.size() > 6) {
      if (boundary[6] != ':') throw OptionError("--boundary", "expected bigtet[:FACTOR]");
      // FACTOR 1 is the smallest tet holding the bounding box: less cannot hold the points.
      const std::string why = check_number(boundary.substr(7), 1, 1e300, false);
      if (!why.empty()) throw OptionError("--boundary", "bigtet FACTOR " + why);
      o.bigtet_factor = std::stod(boundary.substr(7));
    }
  } else {
    throw OptionError("--boundary", "expected infinite or bigtet[:FACTOR], got '" + boundary + "'");
  }
  return o;
}

void KernelOptions::validate() const {
  const auto require = [](const char* option, const std::string& why) {
    if (!why.empty()) throw OptionError(option, why);
  };
  require("--predicates", predicates_error(predicates));
  require("--perturb", choice_error(perturb, kPerturbModes));
  require("--order", choice_error(order, kInsertionOrders));
  char eps_text[32];
  std::snprintf(eps_text, sizeof eps_text, "%.17g", eps);
  require("--eps", check_number(eps_text, 0, kMaxEps, false));
  require("--eps-mode", choice_error(eps_mode, kEpsModes));
  build_options();  // --boundary
}

}  // namespace dtlab
