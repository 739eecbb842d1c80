#include "fracture/site_sources.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>

namespace dtlab {

namespace {
// `count` of the candidates without replacement, each drawn with probability
// proportional to its weight (Gumbel top-k on the log weights, so that far candidates
// with weights below the smallest double still rank).
std::vector<Point3> weighted_subset(const std::vector<Point3>& cand, const std::vector<double>& log_weight,
                                    std::size_t count, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<std::pair<double, std::size_t>> key(cand.size());
  for (std::size_t i = 0; i < cand.size(); ++i) {
    const double u = std::max(U(rng), 1e-300);
    key[i] = {log_weight[i] - std::log(-std::log(u)), i};
  }
  count = std::min(count, cand.size());
  std::partial_sort(key.begin(), key.begin() + static_cast<std::ptrdiff_t>(count), key.end(),
                    [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Point3> out;
  for (std::size_t i = 0; i < count; ++i) out.push_back(cand[key[i].second]);
  return out;
}

std::vector<Point3> candidates(const MeshSampler& sampler, const TriangleMesh& mesh, const SiteOptions& o,
                               const SampleRequest& r) {
  if (o.source == SiteSource::mesh_vertices) return mesh.vertices;
  SampleRequest req = r;
  if (o.impact) req.count = std::min<std::size_t>(16 * r.count, std::max<std::size_t>(r.count, 200000));
  return sampler.sample(req).points;
}

// Uniform in the ball of radius `radius` around each site.
void jitter(std::vector<Point3>& sites, double radius, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (auto& s : sites) {
    Point3 d;
    do d = {U(rng), U(rng), U(rng)};
    while (norm2(d) > 1);
    s += radius * d;
  }
}
}  // namespace

std::vector<Point3> choose_sites(const MeshSampler& sampler, const TriangleMesh& mesh, const SiteOptions& o,
                                 const SampleRequest& r) {
  if (o.impact && o.source == SiteSource::points)
    throw std::invalid_argument("--impact chooses among sampled sites or mesh vertices, not given sites");
  if (o.impact && !(o.impact_radius > 0)) throw std::invalid_argument("--impact-radius must be positive");
  std::mt19937_64 rng(r.seed * 0x9E3779B97F4A7C15ull + 0x51735);
  std::vector<Point3> sites;
  if (o.source == SiteSource::points) {
    sites = o.points;
  } else {
    std::vector<Point3> cand = candidates(sampler, mesh, o, r);
    std::vector<double> log_weight(cand.size(), 0.0);
    if (o.impact)
      for (std::size_t i = 0; i < cand.size(); ++i)
        log_weight[i] = -norm2(cand[i] - *o.impact) / (2 * o.impact_radius * o.impact_radius);
    // Without an impact the sampler's points are already its random choice.
    sites = o.impact || o.source == SiteSource::mesh_vertices ? weighted_subset(cand, log_weight, r.count, rng)
                                                              : std::move(cand);
  }
  if (o.noise > 0) jitter(sites, o.noise * norm(bounding_box(mesh).extent()), rng);
  return sites;
}

}  // namespace dtlab
