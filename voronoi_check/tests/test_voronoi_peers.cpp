// The Voronoi peers in child processes, judged by the exact checker.
#include <catch2/catch.hpp>

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
