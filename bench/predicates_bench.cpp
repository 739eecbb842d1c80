// Micro-benchmark of the predicate backends: ns per call of orient3d and insphere on
// random input (points uniform in [-1,1]^3) and on near-degenerate input (exactly
// coplanar / cospherical integer configurations pushed through a rounded affine map
// or similarity), and on exactly degenerate input (the integer configurations
// themselves: every answer is 0, as on grids), plus the fraction of adaptive calls
// decided by each stage.
//
//   build/<dir>/bench/dtlab_bench_predicates --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "predicates/adaptive.hpp"
#include "predicates/epsilon.hpp"
#include "predicates/exact.hpp"
#include "predicates/naive.hpp"
#include "predicates/perturbed.hpp"
#include "predicates/tests/families.hpp"

namespace {

using namespace dtlab;
using namespace dtlab::test;

constexpr int kN = 4096;

enum Input { kRandom, kNear, kExactDegenerate };

const std::vector<Quad>& quads(Input in) {
  static const std::vector<Quad> data[3] = {
      [] {
        std::mt19937_64 rng(1);
        std::vector<Quad> v(kN);
        for (Quad& q : v)
          for (Point3& p : q) p = random_point(rng);
        return v;
      }(),
      [] {
        std::mt19937_64 rng(2);
        std::vector<Quad> v(kN);
        for (Quad& q : v) {
          const Quad c = coplanar_int_quad(rng);
          const Affine f = random_affine(rng);
          q = {f(c[0]), f(c[1]), f(c[2]), f(c[3])};
        }
        return v;
      }(),
      [] {
        std::mt19937_64 rng(5);
        std::vector<Quad> v(kN);
        for (Quad& q : v) q = coplanar_int_quad(rng);
        return v;
      }()};
  return data[in];
}

const std::vector<Quint>& quints(Input in) {
  static const std::vector<Quint> data[3] = {
      [] {
        std::mt19937_64 rng(3);
        std::vector<Quint> v(kN);
        for (Quint& q : v)
          for (Point3& p : q) p = random_point(rng);
        return v;
      }(),
      [] {
        std::mt19937_64 rng(4);
        std::vector<Quint> v(kN);
        for (Quint& q : v) {
          const Quint c = cospherical_int_quint(rng);
          const Affine f = random_similarity(rng);
          q = {f(c[0]), f(c[1]), f(c[2]), f(c[3]), f(c[4])};
        }
        return v;
      }(),
      [] {
        std::mt19937_64 rng(6);
        std::vector<Quint> v(kN);
        for (Quint& q : v) q = cospherical_int_quint(rng);
        return v;
      }()};
  return data[in];
}

// Time per predicate call (shown with its unit, e.g. 2.5ns).
void per_call(benchmark::State& state) {
  state.counters["per_call"] = benchmark::Counter(
      kN, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

template <class B>
void add_stage_fractions(benchmark::State& state, bool insphere, Input in) {
  if constexpr (std::is_same_v<B, AdaptivePredicates>) {
    AdaptiveStats st;
    const AdaptivePredicates ad{&st};
    if (insphere) {
      for (const Quint& q : quints(in)) ad.insphere(q[0], q[1], q[2], q[3], q[4]);
    } else {
      for (const Quad& q : quads(in)) ad.orient3d(q[0], q[1], q[2], q[3]);
    }
    const auto& c = insphere ? st.insphere : st.orient3d;
    for (int s = 0; s < static_cast<int>(AdaptiveStage::kCount); ++s)
      if (c[s]) {
        std::string key = "%";
        key.append(kAdaptiveStageNames[s].data(), kAdaptiveStageNames[s].size());
        state.counters[key] = 100.0 * static_cast<double>(c[s]) / kN;
      }
  }
}

template <class B>
void bm_orient3d(benchmark::State& state, B b, Input in) {
  const auto& v = quads(in);
  for (auto _ : state) {
    int sum = 0;
    for (const Quad& q : v) sum += b.orient3d(q[0], q[1], q[2], q[3]);
    benchmark::DoNotOptimize(sum);
  }
  per_call(state);
  add_stage_fractions<B>(state, false, in);
}

template <class B>
void bm_insphere(benchmark::State& state, B b, Input in) {
  const auto& v = quints(in);
  for (auto _ : state) {
    int sum = 0;
    for (const Quint& q : v) sum += b.insphere(q[0], q[1], q[2], q[3], q[4]);
    benchmark::DoNotOptimize(sum);
  }
  per_call(state);
  add_stage_fractions<B>(state, true, in);
}

template <class B>
void register_backend(const char* name, B b) {
  for (Input in : {kRandom, kNear, kExactDegenerate}) {
    const std::string suffix =
        in == kRandom ? "/random" : in == kNear ? "/near_degenerate" : "/exact_degenerate";
    benchmark::RegisterBenchmark((std::string("orient3d/") + name + suffix).c_str(),
                                 [b, in](benchmark::State& s) { bm_orient3d(s, b, in); });
    benchmark::RegisterBenchmark((std::string("insphere/") + name + suffix).c_str(),
                                 [b, in](benchmark::State& s) { bm_insphere(s, b, in); });
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_backend("naive", NaivePredicates{});
  register_backend("epsilon_rel", EpsilonPredicates{1e-12, true});
  register_backend("adaptive", AdaptivePredicates{});
  register_backend("perturbed_adaptive", Perturbed<AdaptivePredicates>{});
  register_backend("exact", ExactPredicates{});
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
