// dtlab bench: whole runs of dtlab, CGAL and TetGen on the same points.
#include <malloc.h>

#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bench/whole_run.hpp"
#include "cli/build_options.hpp"
#include "cli/command.hpp"
#include "cli/progress.hpp"
#include "kernel/output_file.hpp"
#include "kernel/parallel_for.hpp"
#include "cli/number_options.hpp"
#include "cli/point_source.hpp"

namespace dtlab::cli {

namespace {

struct BenchArgs {
  std::vector<double> sizes = {1e4, 1e5, 1e6};
  std::vector<std::string> dists = {"uniform"};
  std::vector<std::string> tools = {"dtlab", "cgal", "tetgen"};
  int runs = 3;
  std::uint64_t seed = 1;
  bool json = false;
  bool quiet = false;
  std::string out;
  KernelArgs kernel;
};

int run_bench(const BenchArgs& a) {
  const PredicateSpec spec = a.kernel.predicate_spec();
  const BuildOptions options = a.kernel.build_options();
  nlohmann::json all = nlohmann::json::array();
  if (!a.json) {
    std::printf("| points | distribution | tool | median s | min s | max s | Mpoints/s | peak MB | tets | bytes/tet |\n");
    std::printf("| ---: | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  }
  Progress progress("bench", a.quiet);
  const std::size_t total = a.dists.size() * a.sizes.size() * a.tools.size() * std::size_t(a.runs);
  std::size_t done = 0;
  for (const std::string& dist : a.dists) {
    for (double size : a.sizes) {
      const auto n = static_cast<std::size_t>(size);
      std::vector<Point3> points = generate_points(dist, n, a.seed);
      malloc_trim(0);  // what generating them freed goes back to the system before the children fork
      // Runs alternate between the tools (round r runs every tool once), so that a change
      // of the machine's load spreads over all of them.
      std::vector<BenchRow> rows;
      for (const std::string& tool : a.tools) rows.push_back(BenchRow{dist, n, tool, {}});
      for (int r = 0; r < a.runs; ++r)
        for (BenchRow& row : rows) {
          progress.update("runs", done, total, dist + " n=" + std::to_string(n) + " " + row.tool);
          row.runs.push_back(measure_run(row.tool, points, spec, options, thread_count(a.kernel.threads)));
          ++done;
        }
      for (const BenchRow& row : rows) {
        const std::string& tool = row.tool;
        const bool any = row.median_seconds() > 0;
        const RunMeasure& last = row.runs.back();
        // Measured: the child's peak resident memory over the finite tets.
        const double bytes_per_tet = last.tets ? row.median_peak_mb() * 1048576.0 / double(last.tets) : 0.0;
        nlohmann::json j = {{"distribution", dist}, {"n", n}, {"tool", tool},
                            {"median_s", row.median_seconds()}, {"min_s", row.min_seconds()},
                            {"max_s", row.max_seconds()}, {"peak_mb", row.median_peak_mb()},
                            {"tets", last.tets},
                            {"bytes_per_tet", bytes_per_tet},
                            {"runs", a.runs}, {"note", last.note}};
        // The threads the tool ran on: dtlab and the parallel peers take --threads, the rest is serial.
        j["threads"] = tool == "cgal-parallel" || tool == "gmsh-hxt" || tool == "dtlab" ? thread_count(a.kernel.threads) : 1u;
        all.push_back(j);
        if (a.json) continue;
        if (!any) {
          std::printf("| %zu | %s | %s | no answer (%s) | | | | | | |\n", n, dist.c_str(), tool.c_str(), last.note.c_str());
        } else {
          std::printf("| %zu | %s | %s | %.3f | %.3f | %.3f | %.2f | %.0f | %llu | %s |\n", n, dist.c_str(),
                      tool.c_str(), row.median_seconds(), row.min_seconds(), row.max_seconds(),
                      double(n) / row.median_seconds() / 1e6, row.median_peak_mb(),
                      (unsigned long long)last.tets,
                      std::to_string(int(bytes_per_tet + 0.5)).c_str());
        }
        std::fflush(stdout);
      }
    }
  }
  progress.update("runs", done, total);
  if (a.json) std::printf("%s\n", all.dump(2).c_str());
  if (!a.out.empty()) write_text_file(a.out, all.dump(2) + "\n");
  return kOk;
}

}  // namespace

void add_bench_command(CLI::App& app, int& rc) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* sub = app.add_subcommand("bench", "whole runs of dtlab, CGAL and TetGen on the same points (time, memory)");
  sub->add_option("--sizes", args->sizes, "point counts")->delimiter(',')->transform(count_in(1, 1e9))->capture_default_str();
  sub->add_option("--family,--dist", args->dists,
                  "point families, as fuzz --family: uniform, clustered, lattice, ... (dtlab fuzz --list), mesh "
                  "(--dist is the old spelling)")
      ->delimiter(',')->capture_default_str();
  sub->add_option("--tools", args->tools,
                  "dtlab (on --threads threads), dtlab-serial (one thread), cgal, tetgen; dtlab-cgal-order: serial dtlab "
                  "inserting in CGAL's spatial_sort order; cgal-parallel, gmsh-hxt: the parallel peers on --threads threads")
      ->delimiter(',')
      ->check(CLI::IsMember({"dtlab", "dtlab-serial", "cgal", "tetgen", "dtlab-cgal-order", "cgal-parallel", "gmsh-hxt"}))
      ->capture_default_str();
  sub->add_option("--runs", args->runs, "runs per tool and size (median reported)")->transform(count_in(1, 1000))->capture_default_str();
  sub->add_option("--points-seed", args->seed, "seed of the generated points")->check(seed_value())->capture_default_str();
  sub->add_option("--out", args->out, "also write the rows as JSON to this file")->type_name("FILE");
  sub->add_flag("--json", args->json, "print the rows as JSON instead of a table");
  sub->add_flag("--quiet", args->quiet, "no progress lines on stderr");
  args->kernel.add_to(*sub, kAllKernelOptions | kThreadsOption);
  sub->callback([args, &rc] { rc = run_bench(*args); });
}

}  // namespace dtlab::cli
