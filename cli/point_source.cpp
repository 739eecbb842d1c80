#include "cli/point_source.hpp"

#include <CLI/CLI.hpp>

#include "fuzz/families.hpp"

namespace dtlab::cli {

std::vector<Point3> generate_points(const std::string& source, std::size_t n, std::uint64_t seed) {
  if (const fuzz::Family* f = fuzz::find_family(source)) return f->generate(n, seed);
  throw CLI::ValidationError("--dist", "unknown point source '" + source + "'");
}

}  // namespace dtlab::cli
