#include "cli/point_source.hpp"

#include <CLI/CLI.hpp>

#include "fuzz/families.hpp"
#include "sampling/bumpy_torus.hpp"
#include "sampling/mesh_sampler.hpp"

namespace dtlab::cli {

std::vector<Point3> generate_points(const std::string& source, std::size_t n, std::uint64_t seed) {
  if (const fuzz::Family* f = fuzz::find_family(source)) return f->generate(n, seed);
  if (source == "mesh") {
    // Points inside the built-in bumpy torus (fast winding numbers), as the demo uses.
    const TriangleMesh torus = make_bumpy_torus();
    return MeshSampler(torus).winding(n, seed).points;
  }
  throw CLI::ValidationError("--dist", "unknown point source '" + source + "' (a fuzz family or mesh)");
}

}  // namespace dtlab::cli
