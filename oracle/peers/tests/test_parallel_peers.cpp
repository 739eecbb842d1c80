// The parallel peers (cgal-parallel, gmsh-hxt) at several thread counts: proven
// Delaunay on uniform points and, for CGAL, on cospherical and lattice inputs, with
// the same tets as the serial CGAL in general position; a bad thread count given to
// a helper is a refusal (exit 2), not a crash.
#include <catch2/catch.hpp>

#include <algorithm>

#include "oracle/check/tests/point_sets.hpp"
#include "oracle/peers/peers.hpp"

using namespace dtlab;

namespace {
std::vector<Tet> sorted_tets(std::vector<Tet> tets) {
  for (Tet& k : tets) std::sort(k.begin(), k.end());
  std::sort(tets.begin(), tets.end());
  return tets;
}
}  // namespace

TEST_CASE("parallel peers are proven Delaunay at 1, 2 and 3 threads", "[oracle][peers][threads]") {
  const std::vector<Point3> uniform = test::uniform_points(3000, 4);
  PeerOptions o;
  o.timeout_s = 120;
  const PeerRun serial = run_peer("cgal", uniform, o);
  REQUIRE(serial.verdict == Verdict::delaunay);
  for (unsigned threads : {1u, 2u, 3u}) {
    o.threads = threads;
    for (const std::string name : {"cgal-parallel", "gmsh-hxt"}) {
      INFO(name << " on " << threads << " threads");
      const PeerRun r = run_peer(name, uniform, o);
      if (r.verdict == Verdict::not_installed) {
        WARN(name << " not installed: " << r.message);
        continue;
      }
      INFO(r.message);
      CHECK(r.verdict == Verdict::delaunay);
      // General position: the Delaunay tetrahedralization is unique.
      if (r.mesh) CHECK(sorted_tets(r.mesh->tets) == sorted_tets(serial.mesh->tets));
    }
    for (const auto& points : {test::sphere_points(50), test::lattice_points(5)}) {
      const PeerRun r = run_peer("cgal-parallel", points, o);
      if (r.verdict == Verdict::not_installed) continue;
      INFO("cgal-parallel on " << points.size() << " degenerate points: " << r.message);
      CHECK(r.verdict == Verdict::delaunay);
    }
  }
}

TEST_CASE("a helper refuses a bad thread count by name", "[oracle][peers][threads]") {
  const std::vector<Point3> points = test::uniform_points(50, 2);
  PeerOptions o;
  o.timeout_s = 60;
  o.threads = 5000;  // above the helper's 1024
  const PeerRun r = run_peer("cgal-parallel", points, o);
  if (r.verdict == Verdict::not_installed) return;
  CHECK(r.verdict == Verdict::refused);
  CHECK(r.message.find("bad thread count") != std::string::npos);
}
