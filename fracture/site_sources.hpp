#pragma once
// Where the fracture's sites come from: a volume sampler (default), points given by
// the caller (a file), or the mesh's own vertices; optionally clustered around an
// impact point (density falling off with distance) and jittered. Every choice is
// seeded: the same mesh, options and seed give the same sites.
#include <cstdint>
#include <optional>
#include <vector>

#include "sampling/mesh_sampler.hpp"

namespace dtlab {

enum class SiteSource { sampler, points, mesh_vertices };

struct SiteOptions {
  SiteSource source = SiteSource::sampler;
  std::vector<Point3> points;    // SiteSource::points: used as given (count ignored)
  std::optional<Point3> impact;  // sampled / vertex sites cluster around this point
  double impact_radius = 0;      // Gaussian fall-off of the site density: sigma, mesh units
  double noise = 0;              // jitter, uniform in a ball of noise * bounding-box diagonal
};

// `request.count` sites (all of them for SiteSource::points) for the mesh `sampler`
// holds: the sampler's points, or a seeded subset of the vertices; with an impact,
// `count` of 16 x count candidates drawn with weight exp(-d^2 / 2 r^2) (d: distance to
// the impact point) without replacement; then the jitter. Throws std::invalid_argument
// on an impact with given points or a radius that is not positive.
std::vector<Point3> choose_sites(const MeshSampler& sampler, const TriangleMesh& mesh, const SiteOptions& options,
                                 const SampleRequest& request);

}  // namespace dtlab
