// The Voronoi campaign behind `dtlab fuzz --target voro++`: voro++ loses both copies
// of a duplicated site, so the campaign finds it on the duplicates family, shrinks each
// failure to a 1-minimal input with the same verdict, and saves it with the command
// that replays it; it finds nothing on uniform points.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "experiments/voronoi_campaign.hpp"
#include "kernel/point_io.hpp"
#include "oracle/peers/temp_dir.hpp"
#include "voronoi/voronoi.hpp"

using namespace dtlab;
using namespace dtlab::experiments;

TEST_CASE("fuzz --target voro++: duplicates found and shrunk to 1-minimal", "[voronoi_campaign]") {
  if (voronoi_peer_version("voro++") == "not installed") {
    WARN("voro++ not installed");
    return;
  }
  TempDir dir("dtlab-vcampaign");
  VoronoiCampaignOptions o;
  o.peers = {"voro++"};
  o.sources = fuzz_family_sources({"duplicates", "uniform"});
  o.cases = 2;
  o.max_points = 40;
  o.out_dir = dir.path().string();
  o.peer_options.timeout_s = 60;
  const auto cases = run_voronoi_campaign(o);
  REQUIRE(cases.size() == 4);
  for (const auto& c : cases) {
    INFO(c.source << " case " << c.index << ": " << voronoi_verdict_name(c.run.verdict));
    REQUIRE(c.not_judged.empty());
    if (c.source == "uniform") {
      CHECK(c.run.verdict == VoronoiVerdict::exact_topology);
      CHECK(c.corpus_file.empty());
      continue;
    }
    REQUIRE(c.failed());
    CHECK(c.run.verdict == VoronoiVerdict::wrong_topology);
    CHECK(c.run.report->count(VoronoiDefect::missing_cell) >= 2);  // both copies of a site
    REQUIRE(!c.corpus_file.empty());
    CHECK(c.shrunk_minimal);
    CHECK(c.shrunk_points < c.n);
    CHECK(c.shrunk_verdict == VoronoiVerdict::wrong_topology);
    // The saved input, judged again, fails the same way; removing any point fixes it or
    // makes it unjudgeable (1-minimal, checked here independently of the shrinker).
    const auto saved = read_points((dir.path() / c.corpus_file).string()).points;
    REQUIRE(saved.size() == c.shrunk_points);
    CHECK(run_voronoi_case("voro++", saved, o.peer_options).run.verdict == VoronoiVerdict::wrong_topology);
    for (std::size_t drop = 0; drop < saved.size(); ++drop) {
      auto less = saved;
      less.erase(less.begin() + static_cast<std::ptrdiff_t>(drop));
      const VoronoiCase again = run_voronoi_case("voro++", less, o.peer_options);
      CHECK((!again.not_judged.empty() || again.run.verdict != VoronoiVerdict::wrong_topology));
    }
    std::ifstream sidecar(dir.path() / std::filesystem::path(c.corpus_file).replace_extension(".json"));
    const auto j = nlohmann::json::parse(sidecar);
    CHECK(j["command"].get<std::string>() == "dtlab voronoi " + c.corpus_file + " --against voro++ --json");
    CHECK(j["minimal"].get<bool>());
  }
}

TEST_CASE("Voronoi campaign: flat input is not judged, not a failure", "[voronoi_campaign]") {
  const std::vector<Point3> flat = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 3, 0}};
  const VoronoiCase c = run_voronoi_case("voro++", flat, {});
  CHECK(!c.not_judged.empty());
  CHECK(!c.failed());
}
