#include "experiments/point_sources.hpp"

#include <stdexcept>

#include "fuzz/families.hpp"
#include "sampling/bumpy_torus.hpp"
#include "sampling/mesh_sampler.hpp"

namespace dtlab::experiments {

namespace {
const TriangleMesh& torus() {
  static const TriangleMesh mesh = make_bumpy_torus();
  return mesh;
}
const MeshSampler& torus_sampler() {
  static const MeshSampler sampler(torus());
  return sampler;
}
}  // namespace

bool is_point_source(const std::string& source) {
  if (source.rfind("torus-", 0) == 0) return parse_sample_method(source.substr(6)).has_value();
  return fuzz::find_family(source) != nullptr;
}

std::vector<Point3> experiment_points(const std::string& source, std::size_t n, std::uint64_t seed) {
  if (source.rfind("torus-", 0) == 0) {
    if (auto method = parse_sample_method(source.substr(6))) {
      SampleRequest r;
      r.method = *method;
      r.count = n;
      r.seed = seed;
      return torus_sampler().sample(r).points;
    }
  }
  if (const fuzz::Family* f = fuzz::find_family(source)) return f->generate(n, seed);
  throw std::invalid_argument("unknown point source '" + source + "'");
}

}  // namespace dtlab::experiments
