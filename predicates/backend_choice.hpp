#pragma once
// The runtime choice of backend, made once at the top (CLI, fuzz, bench): a variant
// of the concrete backends; `visit_backend` calls a generic lambda once with the
// chosen backend, wrapped in Perturbed<> when asked, so the callee is instantiated
// per backend and the hot loops see a concrete type.
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "predicates/adaptive.hpp"
#include "predicates/epsilon.hpp"
#include "predicates/exact.hpp"
#include "predicates/interval.hpp"
#include "predicates/naive.hpp"
#include "predicates/perturbed.hpp"
#include "predicates/plugin_predicates.hpp"
#include "predicates/wide_naive.hpp"

namespace dtlab {

using BackendChoice =
    std::variant<NaivePredicates, EpsilonPredicates, AdaptivePredicates, ExactPredicates, LongDoublePredicates,
                 Float128Predicates, IntervalPredicates, PluginPredicates>;

// The built-in backends (a plug-in is "plugin:PATH").
inline constexpr std::string_view kBackendNames[] = {"naive",       "epsilon",  "adaptive", "exact",
                                                     "long-double", "float128", "interval"};

// nullopt for an unknown name. eps and relative configure the epsilon backend only.
// "plugin:PATH" loads a plug-in (predicates/plugin_abi.h) and throws
// std::invalid_argument when it cannot.
inline std::optional<BackendChoice> parse_backend(std::string_view name, double eps = 1e-12,
                                                  bool relative = false) {
  if (name == "naive") return BackendChoice{NaivePredicates{}};
  if (name == "epsilon") return BackendChoice{EpsilonPredicates{eps, relative}};
  if (name == "adaptive") return BackendChoice{AdaptivePredicates{}};
  if (name == "exact") return BackendChoice{ExactPredicates{}};
  if (name == "long-double") return BackendChoice{LongDoublePredicates{}};
  if (name == "float128") return BackendChoice{Float128Predicates{}};
  if (name == "interval") return BackendChoice{IntervalPredicates{}};
  if (name.substr(0, kPluginPrefix.size()) == kPluginPrefix)
    return BackendChoice{PluginPredicates{&load_plugin(std::string(name.substr(kPluginPrefix.size())))}};
  return std::nullopt;
}

inline std::string_view backend_name(const BackendChoice& c) {
  return std::visit([](const auto& b) -> std::string_view { return b.name(); }, c);
}

// f(backend) with backend of type B or Perturbed<B>; returns what f returns (f must
// return the same type for every alternative).
template <class F>
decltype(auto) visit_backend(const BackendChoice& choice, bool perturb, F&& f) {
  return std::visit(
      [&](const auto& b) -> decltype(auto) {
        using B = std::decay_t<decltype(b)>;
        if (perturb) return f(Perturbed<B>{b});
        return f(b);
      },
      choice);
}

}  // namespace dtlab
