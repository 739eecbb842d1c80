// Google Benchmark: the flip-based inserter per backend on uniform points.
// Whole-run comparisons against CGAL and TetGen are `dtlab bench` (bench/whole_run.cpp).
#include <benchmark/benchmark.h>

#include <random>

#include "kernel/build.hpp"

namespace {

std::vector<dtlab::Point3> uniform(std::size_t n) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<dtlab::Point3> pts(n);
  for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
  return pts;
}

void build(benchmark::State& state, const char* backend) {
  const auto pts = uniform(static_cast<std::size_t>(state.range(0)));
  const dtlab::PredicateSpec spec{backend, 1e-12, false, true};
  std::size_t tets = 0;
  for (auto _ : state) {
    auto r = dtlab::build_delaunay(pts, spec);
    tets = r.mesh.tets.size();
    benchmark::DoNotOptimize(tets);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.counters["tets"] = double(tets);
}

void BM_build_naive(benchmark::State& s) { build(s, "naive"); }
void BM_build_adaptive(benchmark::State& s) { build(s, "adaptive"); }
void BM_build_exact(benchmark::State& s) { build(s, "exact"); }

BENCHMARK(BM_build_naive)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_build_adaptive)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_build_exact)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
