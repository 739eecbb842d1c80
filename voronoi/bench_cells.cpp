// Cells extracted per second: dtlab's compute_voronoi (DT, then dual cells, clipping
// only where needed) with 1 and T threads, the all-clipping engine alone, and voro++,
// on the same uniform random points in the unit box. Plain timed run:
//   dtlab_voronoi_bench [N=100000] [SEED=1] [THREADS=0] [only]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <string>
#include <thread>

#include <voro++/voro++.hh>

#include "voronoi/voronoi.hpp"

using namespace dtlab;
using Clock = std::chrono::steady_clock;

static double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 100000;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point3> pts(n);
  for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
  const unsigned threads = argc > 3 ? static_cast<unsigned>(std::atoi(argv[3])) : 0;
  const vor::Box box{{0, 0, 0}, {1, 1, 1}};

  auto cpu = [] { return double(std::clock()) / CLOCKS_PER_SEC; };
  for (unsigned th : {1u, threads}) {
    VoronoiOptions vo;
    vo.box = box;
    vo.predicates = PredicateSpec{"adaptive", 0, false, true};
    vo.threads = th;
    const double c0 = cpu();
    auto w0 = Clock::now();
    VoronoiDiagram vd = compute_voronoi(pts, vo);
    const double wall = since(w0), cpu_s = cpu() - c0;
    double vs = 0;
    for (const auto& c : vd.cells) vs += c.volume;
    std::printf(
        "compute_voronoi threads %u: total %.3f s wall %.3f s CPU; DT %.3f s; cells %.3f s wall %.3f s CPU = %.0f "
        "cells/s wall %.0f cells/CPU-s"
        " (clipped %zu, exact %zu, box-clipped %zu); volume sum - 1 = %.2g\n",
        th ? th : std::thread::hardware_concurrency(), wall, cpu_s, vd.seconds_dt, vd.seconds_cells,
        vd.cpu_seconds_cells, n / vd.seconds_cells, n / vd.cpu_seconds_cells, vd.clipped, vd.exact_clipped,
        vd.box_clipped, vs - 1);
  }

  if (argc > 4 && std::string(argv[4]) == "only") return 0;  // compute_voronoi alone (profiling)
  auto t0 = Clock::now();
  BuildResult dt = build_delaunay(pts, PredicateSpec{"adaptive", 0, false, true});
  const double t_dt = since(t0);
  if (dt.failure) return 1;
  t0 = Clock::now();
  Adjacency adj = delaunay_neighbors(dt.mesh);
  const double t_adj = since(t0);
  t0 = Clock::now();
  vor::ConvexCell cell;
  double sum = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    compute_cell(cell, pts, i, {adj.adj.data() + adj.off[i], adj.off[i + 1] - adj.off[i]}, box, 1e-12,
                 cell_scale(box, pts));
    sum += cell.volume();
  }
  const double t_cells = since(t0);

  t0 = Clock::now();
  // voro++'s guide: about 5 particles per block.
  const int nb = std::max(1, static_cast<int>(std::cbrt(n / 5.0)));
  voro::container con(0, 1, 0, 1, 0, 1, nb, nb, nb, false, false, false, 8);
  for (std::size_t i = 0; i < n; ++i) con.put(static_cast<int>(i), pts[i].x, pts[i].y, pts[i].z);
  voro::c_loop_all loop(con);
  voro::voronoicell c;
  double vsum = 0;
  std::size_t vcells = 0;
  if (loop.start()) do
      if (con.compute_cell(c, loop)) vsum += c.volume(), ++vcells;
    while (loop.inc());
  const double t_voro = since(t0);

  std::printf("points %zu  tets %zu  mean neighbours %.2f\n", n, dt.mesh.tets.size(),
              double(adj.adj.size()) / n);
  std::printf("dtlab DT build        %8.3f s\n", t_dt);
  std::printf("dtlab neighbour lists %8.3f s\n", t_adj);
  std::printf("clipping engine only  %8.3f s  %9.0f cells/s (cells only)  %9.0f cells/s (incl. DT)\n",
              t_cells, n / t_cells, n / (t_cells + t_adj + t_dt));
  std::printf("voro++ cells          %8.3f s  %9.0f cells/s\n", t_voro, vcells / t_voro);
  std::printf("volume sums: dtlab %.15g voro++ %.15g (box 1)\n", sum, vsum);
  return 0;
}
