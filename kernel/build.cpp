// The single runtime dispatch of the kernel: one instantiation of the inserter per
// predicate backend, with and without symbolic perturbation.
#include <stdexcept>

#include "kernel/build_impl.hpp"
#include "predicates/adaptive.hpp"
#include "predicates/epsilon.hpp"
#include "predicates/exact.hpp"
#include "predicates/naive.hpp"
#include "predicates/perturbed.hpp"

namespace dtlab {

const char* failure_name(FailureKind k) {
  switch (k) {
    case FailureKind::walk_cycle: return "walk-cycle";
    case FailureKind::flip_stuck: return "flip-stuck";
    case FailureKind::inconsistent_adjacency: return "inconsistent-adjacency";
    case FailureKind::lower_dimensional: return "lower-dimensional";
    case FailureKind::outside_boundary: return "outside-boundary";
  }
  return "unknown";
}

namespace {
template <PredicateBackend B>
BuildResult build_maybe_perturbed(std::span<const Point3> points, const B& base, bool perturb,
                                  const BuildOptions& options) {
  if (perturb) return build_with(points, Perturbed<B>{base}, options);
  return build_with(points, base, options);
}
}  // namespace

BuildResult build_delaunay(std::span<const Point3> points, const PredicateSpec& spec,
                           const BuildOptions& options) {
  if (spec.backend == "naive") return build_maybe_perturbed(points, NaivePredicates{}, spec.perturb, options);
  if (spec.backend == "exact") return build_maybe_perturbed(points, ExactPredicates{}, spec.perturb, options);
  if (spec.backend == "epsilon")
    return build_maybe_perturbed(points, EpsilonPredicates{spec.eps, spec.relative_eps}, spec.perturb, options);
  if (spec.backend == "adaptive") {
    AdaptiveStats stats;
    BuildResult r = build_maybe_perturbed(points, AdaptivePredicates{&stats}, spec.perturb, options);
    for (int s = 0; s < static_cast<int>(AdaptiveStage::kCount); ++s) {
      const std::string name(kAdaptiveStageNames[s]);
      if (stats.orient3d[s]) r.stats.stages.push_back({"orient3d:" + name, stats.orient3d[s]});
      if (stats.insphere[s]) r.stats.stages.push_back({"insphere:" + name, stats.insphere[s]});
    }
    return r;
  }
  throw std::invalid_argument("unknown predicate backend '" + spec.backend +
                              "' (expected naive, epsilon, adaptive or exact)");
}

}  // namespace dtlab
