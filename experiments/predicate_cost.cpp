#include "experiments/predicate_cost.hpp"

#include <algorithm>
#include <chrono>
#include <random>

#include "experiments/point_sources.hpp"
#include "predicates/adaptive.hpp"
#include "predicates/epsilon.hpp"
#include "predicates/exact.hpp"
#include "predicates/naive.hpp"

namespace dtlab::experiments {

namespace {

template <class Backend>
void measure(const Backend& b, const std::string& label, const std::string& source, const std::vector<Point3>& pts,
             std::size_t calls, std::uint64_t seed, const AdaptivePredicates* counter, nlohmann::json& rows) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint32_t> idx(5 * calls);
  for (auto& i : idx) i = static_cast<std::uint32_t>(rng() % pts.size());
  for (int pred = 0; pred < 2; ++pred) {
    const std::size_t k = pred == 0 ? calls : calls / 4;  // insphere is slower
    long zeros = 0, sum = 0;
    double sec = 1e300;  // best of three passes: the machine may be shared
    for (int rep = 0; rep < 3; ++rep) {
      zeros = 0;
      const auto t0 = std::chrono::steady_clock::now();
      for (std::size_t i = 0; i < k; ++i) {
        const std::uint32_t* q = &idx[5 * i];
        const int s = pred == 0 ? b.orient3d(pts[q[0]], pts[q[1]], pts[q[2]], pts[q[3]])
                                : b.insphere(pts[q[0]], pts[q[1]], pts[q[2]], pts[q[3]], pts[q[4]]);
        zeros += s == 0;
        sum += s;
      }
      sec = std::min(sec, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    // the stages are counted in a second pass: counting costs time of its own
    nlohmann::json stages = nlohmann::json::object();
    if (counter) {
      *counter->stats = AdaptiveStats{};
      for (std::size_t i = 0; i < k; ++i) {
        const std::uint32_t* q = &idx[5 * i];
        sum -= pred == 0 ? counter->orient3d(pts[q[0]], pts[q[1]], pts[q[2]], pts[q[3]])
                         : counter->insphere(pts[q[0]], pts[q[1]], pts[q[2]], pts[q[3]], pts[q[4]]);
      }
      const auto& now = pred == 0 ? counter->stats->orient3d : counter->stats->insphere;
      for (int st = 0; st < static_cast<int>(AdaptiveStage::kCount); ++st)
        if (now[st]) stages[std::string(kAdaptiveStageNames[st])] = now[st];
    }
    rows.push_back({{"points", source}, {"backend", label}, {"predicate", pred == 0 ? "orient3d" : "insphere"},
                    {"calls", k}, {"ns_per_call", 1e9 * sec / double(k)}, {"zeros", zeros},
                    {"checksum", sum}, {"stages", stages}});
  }
}

}  // namespace

nlohmann::json measure_predicate_costs(std::size_t calls, std::uint64_t seed) {
  nlohmann::json rows = nlohmann::json::array();
  for (const std::string source : {"uniform", "ulp_jitter"}) {
    const auto pts = experiment_points(source, 4096, seed);
    measure(NaivePredicates{}, "naive", source, pts, calls, seed, nullptr, rows);
    measure(EpsilonPredicates{1e-12, false}, "epsilon", source, pts, calls, seed, nullptr, rows);
    AdaptiveStats stats;
    const AdaptivePredicates counter{&stats};
    measure(AdaptivePredicates{}, "adaptive", source, pts, calls, seed, &counter, rows);
    measure(ExactPredicates{}, "exact", source, pts, calls / 10, seed, nullptr, rows);
  }
  return rows;
}

}  // namespace dtlab::experiments
