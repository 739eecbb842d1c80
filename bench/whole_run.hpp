#pragma once
// Whole-run benchmarks: dtlab, CGAL and TetGen on the same points, in one process
// tree. Each run happens in a forked child so that its peak memory (ru_maxrss) is
// its own; TetGen runs as a grandchild process and its peak is read the same way.
// A forked child's peak includes the pages it shares with the parent (the points),
// so bytes per tet counts the input as well.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/build.hpp"

namespace dtlab {

struct RunMeasure {
  std::string tool;         // "dtlab", "cgal", "tetgen", "cgal-parallel", ...
  bool ok = false;          // false: the tool gave no answer (crash, missing, timeout)
  double seconds = 0;       // triangulation wall time (TetGen: its whole process)
  double peak_mb = 0;       // peak resident memory (MiB) of the process that built it
  std::uint64_t tets = 0;
  double bytes_per_tet = 0; // measured: peak resident memory / finite tets
  std::string note;
};

// One run of `tool` on `points` in a forked child (the child may consume its copy of
// `points`; the caller's is unchanged). Tools: dtlab (on `threads` threads), dtlab-serial,
// dtlab-cgal-order (serial), cgal, tetgen, and the parallel peers cgal-parallel and
// gmsh-hxt on `threads` threads (in their helper process, as `dtlab oracle` runs them;
// peak memory is the helper's).
RunMeasure measure_run(const std::string& tool, std::vector<Point3>& points,
                       const PredicateSpec& spec, const BuildOptions& options, unsigned threads = 1);

struct BenchRow {
  std::string distribution;
  std::size_t n = 0;
  std::string tool;
  std::vector<RunMeasure> runs;
  double median_seconds() const;
  double min_seconds() const;
  double max_seconds() const;
  double median_peak_mb() const;
};

}  // namespace dtlab
