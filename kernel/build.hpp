#pragma once
// The public entry point of the kernel: the Delaunay tetrahedralization of a point
// set by the one flip-based incremental inserter (kernel/inserter.hpp), with the
// predicate backend chosen at run time (instantiated once per backend in build.cpp).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "kernel/tetrahedralization.hpp"

namespace dtlab {

enum class Boundary { infinite, bigtet };
enum class InsertionOrder { input, brio };

struct BuildOptions {
  Boundary boundary = Boundary::infinite;
  double bigtet_factor = 10.0;  // bigtet size; 1 = the smallest one holding the bounding box
  InsertionOrder order = InsertionOrder::brio;
  std::uint64_t seed = 1;  // walk randomisation and BRIO rounds
  // Count which adaptive stage decided each predicate call (BuildStats::stages): an
  // increment through a pointer on every call, so benchmarks turn it off.
  bool count_stages = true;
  // Threads of the insertion (kernel/README.md, "The parallel build"); 0: all hardware
  // threads, 1: the serial build. With --perturb sos the tets are the same for every
  // count; threaded builds list them in a canonical order (each tet from its smallest
  // vertex, sorted), so their output does not depend on the schedule either.
  unsigned threads = 1;
  // The threaded build's order (above) on any count, one thread included: the threaded
  // build's machinery then runs on one thread (slower than the serial inserter by the
  // claims' cost). `tetra` and `voronoi` set it whenever --threads is given, so that
  // `--threads 1` writes the bytes `--threads 2` writes; without it one thread is the
  // serial build.
  bool canonical_order = false;
  // A pass of the parallel build gives each thread at least this many points (fewer
  // points: fewer threads, down to the serial insertion). Tests and fuzz campaigns set
  // it to 1 so that even small inputs run on every thread.
  std::size_t parallel_grain = 2048;
  // Tet slots per point that the parallel build's shared storage starts with (it grows
  // by half when full, between passes). 7 holds uniform and mesh samples (6.7 tets per
  // point); tests set it tiny so that every input grows many times.
  double parallel_slots_per_point = 7.0;
  // Debug builds: check the whole mesh's invariants after every flip (kernel/mesh_check.hpp;
  // DTLAB_CHECK_COMBINATORICS=1 does the same); serial builds only, slow (a pass over the
  // mesh per flip). Release builds compile the check out and ignore this.
  bool check_combinatorics = false;
  // Keep each facet's mirror in the result (Tetrahedralization::adjacency, 16 bytes per
  // tet), for consumers that would otherwise pair the facets again (the Voronoi
  // checker's tables). A threaded build copies its records before the canonical
  // compaction and finds each in the output afterwards (kernel/canonical_order.hpp):
  // 32 bytes per record more at the end of the build.
  bool keep_adjacency = false;
};

// The runtime predicate choice: backend name (naive|epsilon|adaptive|exact),
// the epsilon band (epsilon backend only) and symbolic perturbation on/off.
struct PredicateSpec {
  std::string backend = "adaptive";
  double eps = 1e-12;
  bool relative_eps = false;
  bool perturb = true;
};

// Named failures of a build. Robust backends never produce the first three on
// valid input; non-robust ones may, and the build stops there.
enum class FailureKind {
  walk_cycle,              // point location exceeded its step bound
  flip_stuck,              // the flip loop exceeded its bound
  inconsistent_adjacency,  // the mesh's adjacency was found broken during insertion
  lower_dimensional,       // fewer than 4 points, or all collinear / coplanar
  outside_boundary,        // --boundary bigtet: a point outside the enclosing tetrahedron
};
const char* failure_name(FailureKind k);

struct BuildFailure {
  FailureKind kind;
  std::int64_t point = -1;  // input index of the point being inserted, -1 if none
  std::string detail;
};

struct BuildStats {
  std::uint64_t inserted = 0;
  std::uint64_t flips14 = 0, flips23 = 0, flips32 = 0, flips44 = 0;
  std::uint64_t walk_steps = 0;
  std::uint64_t mesh_checks = 0;  // check_combinatorics passes run (debug builds)
  std::uint64_t orient3d_calls = 0, insphere_calls = 0;
  // Parallel build: insertions rolled back because another thread held a tet (their
  // flips and predicate calls are counted above), and the threads used.
  std::uint64_t conflicts = 0;
  unsigned threads = 1;
  std::uint64_t storage_growths = 0;  // parallel build: times the shared tet storage grew
  // Parallel build, where the insertion's time goes (kernel/README.md, "Where the threaded
  // insertion loses"): the passes run on threads and their wall seconds; the points
  // attempted on one thread (the prefix, small or non-progressing passes) and their wall
  // seconds; the seconds threads waited at the end of a pass for the last one (summed
  // over the threads) or before their first point (thread start).
  std::uint64_t parallel_passes = 0, serial_points = 0;
  double parallel_seconds = 0, serial_seconds = 0, idle_seconds = 0;
  double seconds = 0;                 // wall time of the insertion loop
  // Which stage of the adaptive predicates decided how many calls ("insphere:A", ...).
  std::vector<std::pair<std::string, std::uint64_t>> stages;
};

struct BuildResult {
  Tetrahedralization mesh;                // compacted finite tets over the input points
  std::vector<std::uint32_t> duplicates;  // inputs equal to an earlier point: not inserted
  std::vector<std::uint32_t> skipped;     // inputs not inserted because the build failed first
  std::optional<BuildFailure> failure;
  BuildStats stats;
  std::size_t peak_tets = 0;  // tet slots allocated (incl. infinite and free)
};

BuildResult build_delaunay(std::span<const Point3> points, const PredicateSpec& predicates,
                           const BuildOptions& options = {});
// The same, taking ownership of the points: they are renumbered in place and come back
// in input order as the result's points, so the build holds one copy of them instead
// of two (24 bytes per point less at the peak).
BuildResult build_delaunay(std::vector<Point3>&& points, const PredicateSpec& predicates,
                           const BuildOptions& options = {});

}  // namespace dtlab
