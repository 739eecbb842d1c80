// dtlab_identity_table [N] [RUNS] [SOURCE]: the identity table of the parallel build (issue 26).
// For every fuzz family and a mesh sample (points inside the bumpy torus), N points
// (default 20000): a 64-bit hash of the sorted canonical tets (kernel/canonical_order.hpp)
// of the serial build and of the threaded build at 1, 2, 3, 4 and 8 threads, RUNS runs each
// (default 2; SOURCE: that point source only), adaptive predicates with --perturb sos.
// DTLAB_SLOTS_PER_POINT=F starts the threaded builds' storage at F tet slots per point
// (BuildOptions::parallel_slots_per_point; e.g. 0.01: every input grows many times).
// Prints a Markdown table; exit 1 when any hash differs from the serial build's (a failing
// build hashes as 0: only an input the serial build also refuses, a lower-dimensional one,
// may fail).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "experiments/point_sources.hpp"
#include "fuzz/families.hpp"
#include "kernel/build.hpp"
#include "kernel/canonical_order.hpp"

using namespace dtlab;

namespace {

// FNV-1a over the canonical tets' ids: the same tet set gives the same hash.
std::uint64_t tets_hash(std::vector<Tet> tets, std::size_t points) {
  canonical_order(tets, points, 1);
  std::uint64_t h = 1469598103934665603ull;
  for (const Tet& t : tets)
    for (const std::uint32_t v : t)
      for (int b = 0; b < 4; ++b) h = (h ^ ((v >> (8 * b)) & 0xFF)) * 1099511628211ull;
  return h;
}

// One row: "| source | points | tets | serial hash | hashes... | equal |"; false on a difference.
bool row(const std::string& source, std::size_t n, int runs) {
  const std::vector<Point3> pts = experiments::experiment_points(source, n, 26);
  const PredicateSpec spec{"adaptive", 0, false, true};
  const BuildResult serial = build_delaunay(pts, spec, BuildOptions{});
  // A failure (a lower-dimensional input) hashes as 0: the threaded builds must fail too.
  const std::uint64_t want = serial.failure ? 0 : tets_hash(serial.mesh.tets, pts.size());
  if (serial.failure)
    std::printf("| %s | %zu | 0 | %s |", source.c_str(), pts.size(), failure_name(serial.failure->kind));
  else
    std::printf("| %s | %zu | %zu | %016llx |", source.c_str(), pts.size(), serial.mesh.tets.size(),
                static_cast<unsigned long long>(want));
  bool same = true;
  for (const unsigned threads : {1u, 2u, 3u, 4u, 8u}) {
    std::string cell = "equal";
    for (int run = 0; run < runs; ++run) {
      BuildOptions o;
      o.threads = threads;
      o.parallel_grain = 64;  // small passes split too: more conflicts, more schedules
      if (const char* f = std::getenv("DTLAB_SLOTS_PER_POINT")) o.parallel_slots_per_point = std::atof(f);
      const BuildResult r = build_delaunay(pts, spec, o);
      const std::uint64_t got = r.failure ? 0 : tets_hash(r.mesh.tets, pts.size());
      if (got != want || r.duplicates != serial.duplicates) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "DIFFERS %016llx", static_cast<unsigned long long>(got));
        cell = buf;
        same = false;
      }
    }
    std::printf(" %s |", cell.c_str());
  }
  std::printf(" %s |\n", same ? "yes" : "NO");
  return same;
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // a row as soon as it is known
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 20000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 2;
  std::printf("| points from | n | tets | hash (serial) | 1 thread | 2 | 3 | 4 | 8 | all equal |\n");
  std::printf("| --- | ---: | ---: | --- | --- | --- | --- | --- | --- | --- |\n");
  const std::string only = argc > 3 ? argv[3] : "";
  bool ok = true;
  for (const fuzz::Family& f : fuzz::families())
    if (only.empty() || only == f.name) ok = row(f.name, n, runs) && ok;
  if (only.empty() || only == "torus-winding") ok = row("torus-winding", n, runs) && ok;
  return ok ? 0 : 1;
}
