#include "experiments/case_grid.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "fuzz/campaign.hpp"
#include "fuzz/case_seed.hpp"
#include "fuzz/families.hpp"
#include "kernel/output_file.hpp"
#include "kernel/point_io.hpp"

namespace dtlab::experiments {

namespace fs = std::filesystem;

std::vector<PointSource> fuzz_family_sources(const std::vector<std::string>& names) {
  std::vector<PointSource> out;
  for (const auto& name : names) {
    const fuzz::Family* f = fuzz::find_family(name);
    if (!f) throw std::invalid_argument("unknown family '" + name + "'");
    out.push_back({f->name, f->generate});
  }
  return out;
}

std::vector<GridCase> grid_cases(const std::vector<std::string>& peers, const CaseGrid& grid) {
  std::vector<GridCase> cases;
  for (const std::string& p : peers)
    for (const PointSource& s : grid.sources)
      for (std::size_t i = 0; i < grid.cases; ++i)
        if (!grid.only_case || *grid.only_case == i)
          cases.push_back({&p, &s, i, fuzz::case_seed(grid.seed, s.name, i)});
  return cases;
}

std::vector<Point3> grid_points(const GridCase& c, const CaseGrid& grid) {
  return c.source->generate(fuzz::case_points(c.seed, grid.min_points, grid.max_points), c.seed);
}

std::string grid_case_command(const std::string& target, const CaseGrid& grid, const std::string& source,
                              std::size_t index) {
  return "dtlab fuzz --target " + target + " --family " + source + " --case " + std::to_string(index) + " --seed " +
         std::to_string(grid.seed) + " --min-points " + std::to_string(grid.min_points) + " --points " +
         std::to_string(grid.max_points) + " --out DIR";
}

double shrink_try_limit(double original_seconds, double timeout_s) {
  return std::clamp(10 * original_seconds, std::min(2.0, timeout_s), timeout_s);
}

std::string corpus_stem(const std::string& peer, const std::string& source, std::size_t n, std::size_t index) {
  std::string stem = peer + "-" + source + "-n" + std::to_string(n) + "-" + std::to_string(index);
  std::replace(stem.begin(), stem.end(), ':', '_');
  return stem;
}

std::string save_corpus_points(const std::string& out_dir, const std::string& stem, const std::vector<Point3>& points) {
  const fs::path dir = fs::path(out_dir) / "corpus";
  fs::create_directories(dir);
  write_node((dir / (stem + ".node")).string(), points);
  return "corpus/" + stem + ".node";
}

void save_corpus_sidecar(const std::string& out_dir, const std::string& stem, const nlohmann::json& sidecar) {
  write_text_file((fs::path(out_dir) / "corpus" / (stem + ".json")).string(), sidecar.dump(2) + "\n");
}

}  // namespace dtlab::experiments
