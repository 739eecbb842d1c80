// dtlab_output_pass [N] [TRIALS] [THREADS]: the cost of the threaded build's output pass
// (compact_canonical, kernel/canonical_order.hpp) against the serial build's compaction, on
// the same records, without the insertion around them (kernel/README.md, "The parallel
// build"). The records are made from a serial build of N uniform points (default 10^6): its
// tets on vertex ids (BRIO ranks), in its slot order, each rotated by an even permutation,
// one dead slot in 33. Prints the median, min and max of TRIALS runs (default 5) of the
// serial compaction, compact_canonical on 1 thread and on THREADS threads (default 2), two
// rounds alternated, with the load average; exit 1 when the output differs from the
// definition (every tet rotated, the list sorted, the ids translated).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "kernel/build_impl.hpp"
#include "kernel/canonical_order.hpp"
#include "kernel/spatial_order.hpp"

using namespace dtlab;

namespace {

std::string load_average() {
  std::FILE* f = std::fopen("/proc/loadavg", "r");
  char line[64] = "?";
  if (f) {
    if (!std::fgets(line, sizeof line, f)) line[0] = 0;
    std::fclose(f);
  }
  std::string s(line);
  return s.substr(0, s.find(' ', s.find(' ', s.find(' ') + 1) + 1));
}

// The serial build's tets as the records of a mesh on vertex ids.
std::vector<TetRecord> records_of(const std::vector<Tet>& tets, const std::vector<std::uint32_t>& rank) {
  std::vector<TetRecord> records;
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const Tet& t = tets[i];
    const std::uint32_t v[4] = {rank[t[0]], rank[t[1]], rank[t[2]], rank[t[3]]};
    const std::size_t s = i % 3;  // an even permutation: a cyclic shift of the last three
    TetRecord r{};
    r.v[0] = v[0], r.v[1] = v[1 + s], r.v[2] = v[1 + (s + 1) % 3], r.v[3] = v[1 + (s + 2) % 3];
    records.push_back(r);
    if (i % 33 == 0) {
      TetRecord dead{};
      dead.v[0] = kNone;
      records.push_back(dead);
    }
  }
  return records;
}

}  // namespace

int main(int argc, char** argv) {
  const auto n = static_cast<std::uint32_t>(argc > 1 ? std::atof(argv[1]) : 1e6);
  const int trials = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  const unsigned threads = argc > 3 ? static_cast<unsigned>(std::atoi(argv[3])) : 2;
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point3> pts(n);
  for (Point3& p : pts) p = {u(rng), u(rng), u(rng)};
  const BuildResult serial = build_delaunay(pts, PredicateSpec{"adaptive", 0, false, true}, BuildOptions{});
  const std::vector<std::uint32_t> order = brio_order(pts, BuildOptions{}.seed);
  std::vector<std::uint32_t> rank(n);
  for (std::uint32_t k = 0; k < n; ++k) rank[order[k]] = k;
  const std::vector<TetRecord> records = records_of(serial.mesh.tets, rank);
  std::vector<Tet> want;  // the definition
  for (const Tet& t : serial.mesh.tets) want.push_back(canonical_tet({rank[t[0]], rank[t[1]], rank[t[2]], rank[t[3]]}));
  std::sort(want.begin(), want.end());
  for (Tet& t : want)
    for (std::uint32_t& v : t) v = order[v];
  std::printf("%u points, %zu tets, %zu slots\n", n, want.size(), records.size());

  std::vector<TetRecord> work(records.size());
  bool same = true;
  const auto run = [&](const char* name, bool canonical, unsigned t) {
    std::vector<double> seconds;
    for (int k = 0; k < trials; ++k) {
      work = records;  // both passes consume the records
      std::vector<Tet> out;
      const auto t0 = std::chrono::steady_clock::now();
      if (canonical)
        compact_canonical(work.data(), work.size(), n, order, out, t);
      else
        detail::compact(work.data(), work.size(), n, order, out);
      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      if (canonical) same = same && out == want;
    }
    std::sort(seconds.begin(), seconds.end());
    std::printf("%-28s median %.4f s [%.4f, %.4f]  load %s\n", name, seconds[seconds.size() / 2], seconds.front(),
                seconds.back(), load_average().c_str());
  };
  const std::string threaded = "compact_canonical, " + std::to_string(threads) + " threads";
  for (int round = 0; round < 2; ++round) {
    run("serial compaction", false, 1);
    run("compact_canonical, 1 thread", true, 1);
    run(threaded.c_str(), true, threads);
  }
  std::printf("output %s the definition\n", same ? "equals" : "DIFFERS FROM");
  return same ? 0 : 1;
}
