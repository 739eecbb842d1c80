// The single runtime dispatch of the kernel: one instantiation of the inserter per
// predicate backend, with and without symbolic perturbation.
#include <cmath>
#include <stdexcept>

#include "kernel/build_impl.hpp"
#include "predicates/backend_choice.hpp"

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

BuildResult build_delaunay(std::span<const Point3> points, const PredicateSpec& spec,
                           const BuildOptions& options) {
  std::vector<Point3> copy;
  copy.reserve(points.size() + 4);  // the build appends the infinite vertex or the bigtet corners
  copy.assign(points.begin(), points.end());
  return build_delaunay(std::move(copy), spec, options);
}

BuildResult build_delaunay(std::vector<Point3>&& points, const PredicateSpec& spec,
                           const BuildOptions& options) {
  // No predicate has a sign for a NaN or an infinity: such input is refused.
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3& p = points[i];
    if (!is_finite(p))
      throw std::invalid_argument("build_delaunay: point " + std::to_string(i) + " has a non-finite coordinate");
  }
  if (options.boundary == Boundary::bigtet && !(std::isfinite(options.bigtet_factor) && options.bigtet_factor > 0))
    throw std::invalid_argument("build_delaunay: bigtet FACTOR must be finite and positive");
  std::optional<BackendChoice> choice = parse_backend(spec.backend, spec.eps, spec.relative_eps);
  if (!choice)
    throw std::invalid_argument("unknown predicate backend '" + spec.backend +
                                "' (expected naive, epsilon, adaptive or exact)");
  AdaptiveStats stages;
  if (auto* adaptive = std::get_if<AdaptivePredicates>(&*choice); adaptive && options.count_stages)
    adaptive->stats = &stages;
  BuildResult r = visit_backend(*choice, spec.perturb,
                                [&](const auto& preds) { return build_with(std::move(points), preds, options); });
  for (int s = 0; s < static_cast<int>(AdaptiveStage::kCount); ++s) {
    const std::string name(kAdaptiveStageNames[s]);
    if (stages.orient3d[s]) r.stats.stages.push_back({"orient3d:" + name, stages.orient3d[s]});
    if (stages.insphere[s]) r.stats.stages.push_back({"insphere:" + name, stages.insphere[s]});
  }
  return r;
}

}  // namespace dtlab
