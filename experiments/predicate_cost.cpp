#include "experiments/predicate_cost.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#include "experiments/point_sources.hpp"
#include "predicates/adaptive.hpp"
#include "predicates/epsilon.hpp"
#include "predicates/exact.hpp"
#include "predicates/naive.hpp"

namespace dtlab::experiments {

namespace {

// 5 points per call; orient3d uses the first 4 of each tuple.
struct Tuples {
  std::vector<Point3> orient, insphere;
};

double unit(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

Tuples make_tuples(const std::string& source, std::size_t calls, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Tuples t;
  t.orient.resize(5 * calls);
  t.insphere.resize(5 * calls);
  if (source == "uniform") {
    const auto pts = experiment_points("uniform", 4096, seed);
    for (auto* v : {&t.orient, &t.insphere})
      for (auto& p : *v) p = pts[rng() % pts.size()];
    return t;
  }
  const auto random_point = [&] { return Point3{unit(rng), unit(rng), unit(rng)}; };
  for (std::size_t i = 0; i < calls; ++i) {
    // orient3d: d = a + s (b - a) + u (c - a), rounded: on the plane up to rounding
    Point3* q = &t.orient[5 * i];
    q[0] = random_point(), q[1] = random_point(), q[2] = random_point();
    const double s = unit(rng), u = unit(rng);
    q[3] = {q[0].x + s * (q[1].x - q[0].x) + u * (q[2].x - q[0].x),
            q[0].y + s * (q[1].y - q[0].y) + u * (q[2].y - q[0].y),
            q[0].z + s * (q[1].z - q[0].z) + u * (q[2].z - q[0].z)};
    q[4] = random_point();
    // insphere: five points centre + r * (unit direction), rounded: cospherical up to rounding
    Point3* e = &t.insphere[5 * i];
    const Point3 centre = random_point();
    const double r = 0.1 + unit(rng);
    for (int k = 0; k < 5; ++k) {
      double x = 2 * unit(rng) - 1, y = 2 * unit(rng) - 1, z = 2 * unit(rng) - 1;
      const double len = std::sqrt(x * x + y * y + z * z);
      if (len < 1e-3) x = 1, y = z = 0;
      else x /= len, y /= len, z /= len;
      e[k] = {centre.x + r * x, centre.y + r * y, centre.z + r * z};
    }
    // a positively oriented a, b, c, d so the sign of insphere means inside / outside
    if (exact_orient3d(e[0], e[1], e[2], e[3]) < 0) std::swap(e[0], e[1]);
  }
  return t;
}

template <class Backend>
void measure(const Backend& b, const std::string& label, const std::string& source, const Tuples& tuples,
             std::size_t calls, const AdaptivePredicates* counter, nlohmann::json& rows) {
  for (int pred = 0; pred < 2; ++pred) {
    const std::size_t k = pred == 0 ? calls : calls / 4;  // insphere is slower
    const std::vector<Point3>& pts = pred == 0 ? tuples.orient : tuples.insphere;
    long zeros = 0, sum = 0;
    double sec = 1e300;  // best of three passes: the machine may be shared
    for (int rep = 0; rep < 3; ++rep) {
      zeros = 0;
      const auto t0 = std::chrono::steady_clock::now();
      for (std::size_t i = 0; i < k; ++i) {
        const Point3* q = &pts[5 * i];
        const int s = pred == 0 ? b.orient3d(q[0], q[1], q[2], q[3]) : b.insphere(q[0], q[1], q[2], q[3], q[4]);
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
        const Point3* q = &pts[5 * i];
        sum -= pred == 0 ? counter->orient3d(q[0], q[1], q[2], q[3]) : counter->insphere(q[0], q[1], q[2], q[3], q[4]);
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
  for (const std::string source : {"uniform", "near_degenerate"}) {
    const Tuples tuples = make_tuples(source, calls, seed);
    measure(NaivePredicates{}, "naive", source, tuples, calls, nullptr, rows);
    measure(EpsilonPredicates{1e-12, false}, "epsilon", source, tuples, calls, nullptr, rows);
    AdaptiveStats stats;
    const AdaptivePredicates counter{&stats};
    measure(AdaptivePredicates{}, "adaptive", source, tuples, calls, &counter, rows);
    measure(ExactPredicates{}, "exact", source, tuples, calls / 10, nullptr, rows);
  }
  return rows;
}

}  // namespace dtlab::experiments
