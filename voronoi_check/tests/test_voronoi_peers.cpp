// The Voronoi peers in child processes, judged by the exact checker.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "sites.hpp"

#include "voronoi_check/voronoi_peers.hpp"

using namespace dtlab;

namespace {

using test::kBox;
using test::random_sites;

VoronoiPeerOptions quick() {
  VoronoiPeerOptions o;
  o.timeout_s = 60;
  return o;
}

}  // namespace

TEST_CASE("every installed Voronoi peer is exact on random sites") {
  const auto sites = random_sites(200, 7);
  for (const auto& name : voronoi_peer_names()) {
    if (name == "dtlab:naive" || name == "dtlab:epsilon") continue;  // not robust: no promise
    const VoronoiPeerRun r = run_voronoi_peer(name, sites, kBox, quick());
    const std::string counts = r.report ? voronoi_counts_text(*r.report) : std::string();
    INFO(name << ": " << voronoi_verdict_name(r.verdict) << " " << r.message << " " << counts);
    if (r.verdict == VoronoiVerdict::not_installed) {
      WARN(name << " not installed: " << r.message);
      continue;
    }
    REQUIRE(r.report);
    CHECK(r.report->topology == Topology::exact);
    CHECK(r.verdict == VoronoiVerdict::exact_topology);
    CHECK(r.report->cells == 200);
  }
}

TEST_CASE("voro++ loses both copies of a duplicated site") {
  auto sites = random_sites(100, 8);
  sites.push_back(sites[5]);
  const VoronoiPeerRun r = run_voronoi_peer("voro++", sites, kBox, quick());
  if (r.verdict == VoronoiVerdict::not_installed) {
    WARN("voro++ not installed");
    return;
  }
  REQUIRE(r.report);
  INFO(voronoi_counts_text(*r.report));
  CHECK(r.report->count(VoronoiDefect::missing_cell) == 1);
  CHECK(r.verdict == VoronoiVerdict::wrong_topology);
  // dtlab's own cells keep one cell for the pair.
  const VoronoiPeerRun ours = run_voronoi_peer("dtlab:adaptive", sites, kBox, quick());
  CHECK(ours.verdict == VoronoiVerdict::exact_topology);
}

TEST_CASE("dtlab's own cells as a peer refuse what dtlab voronoi refuses") {
  // A 4x4x3 grid of sites one ulp of 0.5 apart: the exact Delaunay complex exists, but
  // cells clipped in doubles collapse. `dtlab voronoi` exits 2 on it; the dtlab:BACKEND
  // peer answered such cells (wrong-topology) before.
  std::vector<Point3> sites;
  const double u = std::nextafter(0.5, 1.0) - 0.5;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 3; ++k) sites.push_back({0.5 + i * u, 0.5 + j * u, 0.5 + k * u});
  const vor::Box box{{0.5 - 8 * u, 0.5 - 8 * u, 0.5 - 8 * u}, {0.5 + 12 * u, 0.5 + 12 * u, 0.5 + 12 * u}};
  const VoronoiPeerRun r = run_voronoi_peer("dtlab:adaptive", sites, box, quick());
  INFO(voronoi_verdict_name(r.verdict) << " " << r.message);
  CHECK(r.verdict == VoronoiVerdict::refused);
  CHECK(r.message.find("double precision") != std::string::npos);
}

TEST_CASE("dtlab's own cells as a peer refuse sites and boxes out of dtlab voronoi's range") {
  std::vector<Point3> far = random_sites(20, 9);
  far.push_back({2e100, 0.5, 0.5});
  const VoronoiPeerRun sites = run_voronoi_peer("dtlab:adaptive", far, kBox, quick());
  CHECK(sites.verdict == VoronoiVerdict::refused);
  CHECK(sites.message.find("site coordinates beyond 1e100") != std::string::npos);
  const vor::Box huge{{0, 0, 0}, {2e101, 1, 1}};
  const VoronoiPeerRun box = run_voronoi_peer("dtlab:adaptive", random_sites(20, 9), huge, quick());
  CHECK(box.verdict == VoronoiVerdict::refused);
  CHECK(box.message.find("--box: corners beyond 1e101") != std::string::npos);
}

TEST_CASE("a peer that is not there, or that writes garbage, is named so") {
  VoronoiPeerOptions o = quick();
  o.helper = "/nonexistent/dtlab_voronoi_peer";
  CHECK(run_voronoi_peer("voro++", random_sites(20, 9), kBox, o).verdict == VoronoiVerdict::not_installed);
  o.helper = "/bin/true";  // exits 0 and writes nothing
  const auto r = run_voronoi_peer("voro++", random_sites(20, 9), kBox, o);
  CHECK(r.verdict == VoronoiVerdict::refused);
  CHECK(r.message.find("malformed answer") != std::string::npos);
  CHECK_THROWS_AS(run_voronoi_peer("nope", random_sites(20, 9), kBox, o), std::invalid_argument);
}

namespace {

// The sites' bounding box grown by 10% of its extent per side (dtlab voronoi's default).
vor::Box grown_box(const std::vector<Point3>& s) {
  vor::Box b{s[0], s[0]};
  for (const auto& p : s) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  const Point3 m = 0.1 * (b.hi - b.lo);
  return {b.lo - m, b.hi + m};
}

}  // namespace

// Qhull lists a Voronoi ridge only with 3 vertices or more (infinity counted once), so the
// face of a hull edge with one tet around it (a wedge: one finite vertex, two rays) is in no
// ridge of scipy's ridge_points nor of `qvoronoi Fv`; the adapter takes those neighbours from
// the tool's regions (voronoi_check/README.md). Inputs: voronoi_check/corpus/, shrunk by
// `dtlab fuzz --target scipy-voronoi|qvoronoi --family uniform` with the adapter before.
TEST_CASE("scipy-voronoi and qvoronoi keep the faces of hull edges with one tet") {
  // 4 sites, one tet: scipy lists no ridge at all (the old adapter made no cell).
  const std::vector<Point3> four = {{0.9577314449920443, 0.6327793038290165, 0.15208938114568094},
                                    {0.3349229014298386, 0.735562357242233, 0.6843961158156141},
                                    {0.5570683787113921, 0.30868276277966955, 0.6176198020723661},
                                    {0.811109233013189, 0.034099984568699226, 0.4751613964455029}};
  // 5 sites (qvoronoi refuses 4): a face of 0.38 of the extent squared was missing (both
  // directions); 48 sites (seed 14): two missing faces.
  std::vector<Point3> five = four;
  five.insert(five.begin(), Point3{0.1854999474475154, 0.994560442734284, 0.2857630581968347});
  const std::vector<Point3> uniform48 = random_sites(48, 14);
  for (const std::vector<Point3>* sites : std::vector<const std::vector<Point3>*>{&four, &five, &uniform48})
    for (const char* name : {"scipy-voronoi", "qvoronoi"}) {
      if (sites == &four && std::string(name) == "qvoronoi") continue;
      const VoronoiPeerRun r = run_voronoi_peer(name, *sites, grown_box(*sites), quick());
      if (r.verdict == VoronoiVerdict::not_installed) {
        WARN(name << " not installed: " << r.message);
        continue;
      }
      REQUIRE(r.report);
      INFO(name << " on " << sites->size() << " sites: " << voronoi_verdict_name(r.verdict) << " "
                << voronoi_counts_text(*r.report));
      CHECK(r.verdict == VoronoiVerdict::exact_topology);
      CHECK(r.report->cells == sites->size());
    }
}
