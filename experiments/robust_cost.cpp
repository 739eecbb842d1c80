// What robustness costs: the same inputs built with every backend (median wall time
// of in-process builds), the exact check of one result each, and the adaptive
// predicates' stage statistics (which stage decided how many calls). Runs: 5 (quick:
// 3; exact at 10^5: 1), interleaved over the backends.
#include <algorithm>
#include <chrono>

#include "experiments/point_sources.hpp"
#include "experiments/report.hpp"
#include "experiments/thesis_parts.hpp"
#include "fuzz/outcome.hpp"
#include "oracle/check/check.hpp"

namespace dtlab::experiments {

nlohmann::json cost_section(const SectionContext& c) {
  const std::vector<std::string> sources = {"uniform", "torus-rays", "ulp_jitter"};
  const std::vector<std::size_t> sizes = c.quick ? std::vector<std::size_t>{1000, 10000}
                                                 : std::vector<std::size_t>{10000, 100000};
  const int runs = c.quick ? 3 : 5;
  const std::vector<PredicateSpec> backends = {{"naive", 0, false, false}, {"epsilon", 1e-12, false, false},
                                               {"adaptive", 0, false, true}, {"exact", 0, false, true}};
  std::vector<std::vector<std::string>> rows;
  nlohmann::json cells = nlohmann::json::array();
  for (const auto& src : sources)
    for (std::size_t n : sizes) {
      const std::uint64_t s = case_seed(c.seed, "cost/" + src, n, 0);
      const auto points = experiment_points(src, n, s);
      BuildOptions opt;
      opt.seed = s;
      // Runs interleave the backends (naive, epsilon, adaptive, exact, naive, ...) so a
      // change of the machine's load hits all of them alike.
      std::vector<std::vector<double>> times(backends.size());
      std::vector<BuildResult> results(backends.size());
      for (int r = 0; r < runs; ++r)
        for (std::size_t b = 0; b < backends.size(); ++b) {
          // exact at 10^5 takes seconds per build: one run
          if (r > 0 && backends[b].backend == "exact" && n >= 100000) continue;
          const auto t0 = std::chrono::steady_clock::now();
          results[b] = build_delaunay(points, backends[b], opt);
          times[b].push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
      for (std::size_t b = 0; b < backends.size(); ++b) {
        const PredicateSpec& spec = backends[b];
        std::vector<double>& t = times[b];
        const BuildResult& last = results[b];
        const int reps = static_cast<int>(t.size());
        std::sort(t.begin(), t.end());
        CheckOptions co;
        co.duplicates = last.duplicates;
        const CheckReport check = check_tetrahedralization(last.mesh, co);
        const std::string failure = last.failure ? failure_name(last.failure->kind) : "";
        nlohmann::json stages = nlohmann::json::object();
        for (const auto& [name, calls] : last.stats.stages) stages[name] = calls;
        const std::string label = fuzz::backend_label(spec);
        cells.push_back({{"source", src}, {"n", points.size()}, {"backend", label}, {"median_s", t[t.size() / 2]}, {"runs", reps},
                         {"min_s", t.front()}, {"max_s", t.back()}, {"defects", check.defect_count()},
                         {"failure", failure}, {"orient3d_calls", last.stats.orient3d_calls},
                         {"insphere_calls", last.stats.insphere_calls}, {"stages", stages}});
        rows.push_back({src, std::to_string(points.size()), label, fmt("%.5f", t[t.size() / 2]), fmt("%.5f", t.front()),
                        fmt("%.5f", t.back()), std::to_string(check.defect_count()), failure,
                        std::to_string(last.stats.orient3d_calls), std::to_string(last.stats.insphere_calls)});
      }
    }
  write_csv(c.dir / "data" / "cost.csv",
            {"source", "n", "backend", "median_s", "min_s", "max_s", "defects", "failure", "orient3d_calls",
             "insphere_calls"},
            rows);
  return {{"sources", sources}, {"sizes", sizes}, {"runs", runs}, {"cells", cells}};
}

}  // namespace dtlab::experiments
