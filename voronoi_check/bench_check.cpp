// The exact Voronoi checker's cost against our own cells' (issue 27's "checking a
// tool's 10^5 cells costs at most the time our own cells take to compute"): per round,
// on the same uniform sites in the unit cube, our cells (compute_voronoi: the DT and
// the cells), voro++'s cells, the check of each; the order alternates between rounds.
// A plain timed run, no test asserts a time:
//   dtlab_voronoi_check_bench [N=100000] [ROUNDS=3] [THREADS=1] [SEED=1] [ULPS=4]
// THREADS is used by both our cells and the checker; ULPS is the checker's ulp floor K
// (VoronoiCheckOptions::ulps; 0: the relative tolerances alone, the checker before it).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "voronoi/voronoi.hpp"
#include "voronoi_check/voronoi_check.hpp"
#include "voronoi_check/voronoi_peer_programs.hpp"

using namespace dtlab;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Series {
  std::string name;
  std::vector<double> s;
  void print() const {
    std::vector<double> v = s;
    std::sort(v.begin(), v.end());
    std::printf("%-22s min %.3f  median %.3f  max %.3f s\n", name.c_str(), v.front(), v[v.size() / 2], v.back());
  }
};

void print_stages(const char* what, const VoronoiCheckReport& r) {
  std::printf("  %s: %s, DT %.3f tables %.3f relation %.3f geometry %.3f total %.3f s\n", what,
              voronoi_verdict_name(r.verdict), r.seconds_dt, r.seconds_tables, r.seconds_relation, r.seconds_geometry,
              r.seconds);
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 100000;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 3;
  const unsigned threads = argc > 3 ? static_cast<unsigned>(std::atoi(argv[3])) : 1;
  const std::uint64_t seed = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 1;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point3> pts(n);
  for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
  const vor::Box box{{0, 0, 0}, {1, 1, 1}};
  VoronoiCheckOptions co;
  co.threads = threads;
  if (argc > 5) co.ulps = std::strtod(argv[5], nullptr);

  Series ours{"our cells (DT+cells)", {}}, voro{"voro++ cells", {}}, check_ours{"check of our cells", {}},
      check_voro{"check of voro++'s", {}}, check_reuse{"same, our DT reused", {}};
  for (int round = 0; round < rounds; ++round) {
    VoronoiDiagram vd;
    PeerCells vc;
    const std::function<void()> our_cells = [&] {
      VoronoiOptions vo;
      vo.box = box;
      vo.threads = threads;
      vo.build.threads = threads;
      vo.keep_dt = true;
      const auto t0 = Clock::now();
      vd = compute_voronoi(pts, vo);
      ours.s.push_back(since(t0));
      std::printf("  our cells: DT %.3f cells %.3f s\n", vd.seconds_dt, vd.seconds_cells);
    };
    const std::function<void()> voro_cells = [&] {
      vc = peer_voro(pts, box);
      voro.s.push_back(vc.seconds);
    };
    const auto check = [&](Series& into, const char* what, const ToolCells& cells, bool reuse) {
      VoronoiCheckOptions o = co;
      if (reuse) o.dt = vd.dt;
      const VoronoiCheckReport r = check_voronoi(pts, box, cells, o);
      into.s.push_back(r.seconds);
      print_stages(what, r);
    };
    const std::vector<std::function<void()>> checks = {
        [&] { check(check_ours, "check of ours", tool_cells_of(vd), false); },
        [&] { check(check_voro, "check of voro++'s", vc.cells, false); },
        [&] { check(check_reuse, "check of voro++'s, our DT", vc.cells, true); }};
    if (round % 2 == 0) {
      our_cells(), voro_cells();
      for (const auto& c : checks) c();
    } else {
      voro_cells(), our_cells();
      for (auto c = checks.rbegin(); c != checks.rend(); ++c) (*c)();
    }
  }
  std::printf("n %zu, %d rounds, %u thread(s)\n", n, rounds, threads);
  for (const Series* s : {&ours, &check_ours, &voro, &check_voro, &check_reuse}) s->print();
  return 0;
}
