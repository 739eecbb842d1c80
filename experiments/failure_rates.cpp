// Failure rates of the non-robust and robust backends (rates_section) and of the
// tolerance "fix" over a sweep of eps (epsilon_section).
#include <sstream>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <fstream>
#include <map>

#include "kernel/output_file.hpp"
#include "experiments/point_sources.hpp"
#include "experiments/report.hpp"
#include "experiments/thesis_parts.hpp"
#include "fuzz/outcome.hpp"
#include "fuzz/rate_interval.hpp"

namespace dtlab::experiments {

namespace {

std::uint64_t mix(std::uint64_t x) {  // SplitMix64 finalizer
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

std::uint64_t count(const fuzz::CaseRun& r, const char* kind) {
  auto it = r.defects.find(kind);
  return it == r.defects.end() ? 0 : it->second;
}

// What went wrong in one case, in the thesis's words.
struct Tally {
  int cases = 0, failed = 0, crash = 0, overlap = 0, missing = 0, non_delaunay = 0;
  double build_ms = 0;
  std::map<std::string, int> outcomes;
  void add(const fuzz::CaseRun& r) {
    ++cases;
    build_ms += 1e3 * r.build_seconds;
    ++outcomes[r.outcome];
    if (r.ok()) return;
    ++failed;
    // a stopped build is not checked: the points after the one it stopped at are missing
    const bool stopped = r.outcome == "walk-cycle" || r.outcome == "flip-stuck" ||
                         r.outcome == "inconsistent-adjacency" || r.outcome == "exception";
    crash += stopped;
    if (count(r, "overlap") + count(r, "inverted") + count(r, "flat") + count(r, "broken-adjacency")) ++overlap;
    if (stopped || count(r, "missing-point")) ++missing;
    if (count(r, "non-delaunay")) ++non_delaunay;
  }
  double rate(int k) const { return cases ? double(k) / cases : 0; }
  nlohmann::json json() const {
    const fuzz::RateInterval r = fuzz::wilson_interval(failed, cases);
    return {{"cases", cases}, {"failed", failed}, {"rate", r.rate}, {"ci95_low", r.low}, {"ci95_high", r.high},
            {"crash", crash}, {"overlap_inverted", overlap},
            {"missing_point", missing}, {"non_delaunay", non_delaunay},
            {"mean_build_ms", cases ? build_ms / cases : 0}, {"outcomes", outcomes}};
  }
};

// f(i) for i in [0, count), on every hardware thread; results stay in index order.
template <class F>
auto parallel_cases(int count, F f) {
  std::vector<decltype(f(0))> out(count);
  std::atomic<int> next{0};
  const unsigned threads = std::max(1u, std::min(std::thread::hardware_concurrency(), unsigned(count)));
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t)
    pool.emplace_back([&] {
      for (int i = next++; i < count; i = next++) out[i] = f(i);
    });
  for (auto& th : pool) th.join();
  return out;
}

std::string outcomes_text(const std::map<std::string, int>& m) {
  std::string s;
  for (const auto& [k, v] : m) s += (s.empty() ? "" : " ") + k + ":" + std::to_string(v);
  return s;
}

}  // namespace

std::uint64_t case_seed(std::uint64_t seed, const std::string& what, std::uint64_t n, std::uint64_t index) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a of the name
  for (unsigned char ch : what) h = (h ^ ch) * 1099511628211ull;
  return mix(mix(mix(seed) ^ h) ^ n) ^ mix(index);
}

nlohmann::json rates_section(const SectionContext& c) {
  const std::vector<std::string> families =
      c.quick ? std::vector<std::string>{"uniform", "near_degenerate", "ulp_jitter", "torus-rays"}
              : std::vector<std::string>{"uniform", "clustered", "near_degenerate", "ulp_jitter",
                                         "kettner_grid", "torus-rays", "torus-winding"};
  const std::vector<std::size_t> sizes = c.quick ? std::vector<std::size_t>{16, 64, 256}
                                                 : std::vector<std::size_t>{16, 64, 256, 1024, 4096};
  const int cases = c.quick ? 4 : 64;
  // The thesis's four, then the wider naive types (does precision fix it?), the interval
  // filter with its exact fallback, and any extra backend asked for.
  std::vector<PredicateSpec> backends = {{"naive", 0, false, false},       {"epsilon", 1e-12, false, false},
                                         {"adaptive", 0, false, true},     {"exact", 0, false, true},
                                         {"long-double", 0, false, false}, {"float128", 0, false, false},
                                         {"interval", 0, false, true}};
  backends.insert(backends.end(), c.extra_backends.begin(), c.extra_backends.end());
  std::vector<std::string> labels;
  for (const auto& spec : backends) labels.push_back(fuzz::backend_label(spec));
  std::vector<std::vector<std::string>> rows;
  nlohmann::json cells = nlohmann::json::array();
  for (const auto& fam : families)
    for (std::size_t n : sizes) {
      std::map<std::string, Tally> per_backend;
      const auto runs = parallel_cases(cases, [&](int i) {
        const std::uint64_t s = case_seed(c.seed, fam, n, i);
        const auto points = experiment_points(fam, n, s);
        BuildOptions opt;
        opt.seed = s;
        std::vector<fuzz::CaseRun> r;
        for (const auto& spec : backends) r.push_back(fuzz::run_case(points, spec, opt));
        return r;
      });
      for (const auto& r : runs)
        for (std::size_t b = 0; b < backends.size(); ++b) per_backend[fuzz::backend_label(backends[b])].add(r[b]);
      for (const auto& spec : backends) {
        const std::string label = fuzz::backend_label(spec);
        const Tally& t = per_backend[label];
        nlohmann::json j = t.json();
        j["family"] = fam;
        j["n"] = n;
        j["backend"] = label;
        cells.push_back(j);
        rows.push_back({label, fam, std::to_string(n), std::to_string(t.cases), std::to_string(t.failed),
                        fmt("%.4f", t.rate(t.failed)), fmt("%.4f", j["ci95_low"]), fmt("%.4f", j["ci95_high"]),
                        std::to_string(t.crash), std::to_string(t.overlap),
                        std::to_string(t.missing), std::to_string(t.non_delaunay),
                        fmt("%.3f", t.cases ? t.build_ms / t.cases : 0), outcomes_text(t.outcomes)});
      }
    }
  write_csv(c.dir / "data" / "rates.csv",
            {"backend", "family", "n", "cases", "failed", "failure_rate", "ci95_low", "ci95_high", "crash", "overlap_inverted",
             "missing_point", "non_delaunay", "mean_build_ms", "outcomes"},
            rows);
  return {{"families", families}, {"sizes", sizes}, {"cases", cases}, {"cells", cells}, {"labels", labels},
          {"backends", {"naive", "epsilon (eps 1e-12, absolute)", "adaptive+sos", "exact+sos"}}};
}

nlohmann::json epsilon_section(const SectionContext& c) {
  const std::vector<std::string> families =
      c.quick ? std::vector<std::string>{"near_degenerate", "ulp_jitter"}
              : std::vector<std::string>{"clustered", "near_degenerate", "ulp_jitter", "kettner_grid", "torus-rays"};
  const std::size_t n = c.quick ? 128 : 256;
  const int cases = c.quick ? 4 : 64;
  std::vector<double> eps;
  for (int k = -20; k <= -2; k += c.quick ? 6 : 2) eps.push_back(std::pow(10.0, k));
  std::vector<std::vector<std::string>> rows;
  nlohmann::json cells = nlohmann::json::array();
  // eps = 0 is the naive backend (the baseline the tolerance was meant to fix)
  for (const auto& fam : families) {
    std::vector<std::vector<Point3>> inputs;
    std::vector<std::uint64_t> seeds;
    for (int i = 0; i < cases; ++i) {
      seeds.push_back(case_seed(c.seed, "eps/" + fam, n, i));
      inputs.push_back(experiment_points(fam, n, seeds.back()));
    }
    for (int mode = 0; mode < 3; ++mode) {
      const std::vector<double> sweep = mode == 0 ? std::vector<double>{0.0} : eps;
      for (double e : sweep) {
        PredicateSpec spec{mode == 0 ? "naive" : "epsilon", e, mode == 2, false};
        Tally t;
        for (const auto& r : parallel_cases(cases, [&](int i) {
               BuildOptions opt;
               opt.seed = seeds[i];
               return fuzz::run_case(inputs[i], spec, opt);
             }))
          t.add(r);
        const char* m = mode == 0 ? "naive" : mode == 1 ? "absolute" : "relative";
        nlohmann::json j = t.json();
        j["family"] = fam;
        j["mode"] = m;
        j["eps"] = e;
        cells.push_back(j);
        rows.push_back({fam, m, fmt("%.0e", e), std::to_string(n), std::to_string(t.cases), std::to_string(t.failed),
                        fmt("%.4f", t.rate(t.failed)), fmt("%.4f", j["ci95_low"]), fmt("%.4f", j["ci95_high"]),
                        std::to_string(t.crash), std::to_string(t.overlap),
                        std::to_string(t.missing), std::to_string(t.non_delaunay), outcomes_text(t.outcomes)});
      }
    }
  }
  write_csv(c.dir / "data" / "epsilon.csv",
            {"family", "mode", "eps", "n", "cases", "failed", "failure_rate", "ci95_low", "ci95_high", "crash", "overlap_inverted",
             "missing_point", "non_delaunay", "outcomes"},
            rows);
  return {{"families", families}, {"n", n}, {"cases", cases}, {"eps", eps}, {"cells", cells}};
}

}  // namespace dtlab::experiments
