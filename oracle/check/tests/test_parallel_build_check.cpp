// The threaded build (kernel/README.md, "The parallel build") proven by the exact
// checker: without perturbation, on degenerate input (a lattice, points on one sphere),
// every threaded build is a Delaunay tetrahedralization, the cover of the hull included,
// at 2, 3, 4 and 8 threads, several runs (the schedules differ from run to run).
#include <catch2/catch.hpp>

#include "kernel/build.hpp"
#include "oracle/check/check.hpp"
#include "oracle/check/tests/point_sets.hpp"

using namespace dtlab;

namespace {

void require_proven(const std::vector<Point3>& pts, unsigned threads, std::uint64_t seed) {
  BuildOptions o;
  o.threads = threads;
  o.parallel_grain = 1;  // every pass split between the threads, however small
  o.seed = seed;
  BuildResult r = build_delaunay(pts, PredicateSpec{"adaptive", 0, false, false}, o);
  REQUIRE_FALSE(r.failure);
  CHECK(r.stats.threads == threads);
  CheckOptions c;
  c.duplicates = r.duplicates;
  const CheckReport report = check_tetrahedralization(r.mesh, c);
  CHECK(report.ok());
  CHECK(report.stats.cover_proven);
}

}  // namespace

TEST_CASE("threaded build without perturbation: the exact checker proves it Delaunay", "[threads][build]") {
  const std::vector<Point3> lattice = test::lattice_points(11), sphere = test::sphere_points(2025);
  for (unsigned threads : {2u, 3u, 4u, 8u})
    for (std::uint64_t run = 0; run < 3; ++run) {
      INFO("threads " << threads << " run " << run);
      require_proven(lattice, threads, run);
      require_proven(sphere, threads, run);
    }
}
