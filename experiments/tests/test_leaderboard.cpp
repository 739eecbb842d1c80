// The leaderboard end to end on a small field: the report, the CSV with one row per
// case, environment.json with the peers' versions, and a shrunk failing input for a
// peer that fails (dtlab:naive on near-degenerate points), reproducible from its file.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "experiments/leaderboard.hpp"
#include "experiments/peer_campaign.hpp"
#include "kernel/point_io.hpp"
#include "oracle/peers/peers.hpp"
#include "oracle/peers/temp_dir.hpp"
#include "voronoi_check/voronoi_peers.hpp"

using namespace dtlab;

TEST_CASE("leaderboard: report, csv, environment and shrunk failures", "[experiments][leaderboard]") {
  TempDir dir;
  experiments::LeaderboardOptions o;
  o.out = dir.path() / "board";
  o.quick = true;
  o.peers = {"cgal", "dtlab:naive+none", "tetgen"};
  o.families = {"uniform", "kettner_grid", "near_degenerate"};
  o.cases = 3;
  o.meshes = false;
  o.speed_n = 2000;
  o.jobs = 2;
  o.shrink_runs = 6;  // too few for one pass: later passes go on
  o.shrink_seconds = 120;
  o.voronoi_peers = {"voro++"};  // the Voronoi section with one peer
  const auto r = experiments::run_leaderboard(o);
  CHECK(r.exit_code == 0);
  for (const char* f : {"report.md", "report.html", "leaderboard.csv", "environment.json", "data/speed.csv"})
    CHECK(std::filesystem::exists(o.out / f));

  std::ifstream csv(o.out / "leaderboard.csv");
  std::string line;
  std::getline(csv, line);
  CHECK(line.rfind("peer,source,n,case,seed,", 0) == 0);
  CHECK(line.find(",shrunk_points,shrink_ended,shrink_passes,shrink_runs,shrink_seconds,") != std::string::npos);
  std::size_t rows = 0, cgal_delaunay = 0, more_passes = 0;
  while (std::getline(csv, line)) {
    ++rows;
    if (line.rfind("cgal,", 0) == 0 && line.find(",delaunay,") != std::string::npos) ++cgal_delaunay;
    if (line.find(",1-minimal,") != std::string::npos && line.find(",1-minimal,1,") == std::string::npos)
      ++more_passes;  // 1-minimal after more than one pass
  }
  CHECK(rows == 3 * 3 * 3);
  CHECK(cgal_delaunay == 3 * 3);  // CGAL is right on every case

  const auto env = nlohmann::json::parse(std::ifstream(o.out / "environment.json"));
  CHECK(env["peers"]["cgal"].get<std::string>().rfind("CGAL", 0) == 0);

  // Every shrunk input still gives its recorded verdict.
  std::size_t checked = 0;
  if (std::filesystem::exists(o.out / "corpus"))
  for (const auto& e : std::filesystem::directory_iterator(o.out / "corpus")) {
    if (e.path().extension() != ".json") continue;
    const auto side = nlohmann::json::parse(std::ifstream(e.path()));
    const auto points = read_node((o.out / side["file"].get<std::string>()).string()).points;
    const PeerRun again = run_peer(side["peer"], points);
    CHECK(std::string(verdict_name(again.verdict)) == side["verdict"].get<std::string>());
    CHECK(points.size() <= side["points_original"].get<std::size_t>());
    CHECK(side["shrunk_run"]["verdict"] == side["verdict"]);  // the fresh re-run agrees
    if (!side["minimal"].get<bool>()) CHECK(!side["shrink_stopped_by"].get<std::string>().empty());
    ++checked;
  }
  const std::string report = [&] {
    std::ostringstream s;
    s << std::ifstream(o.out / "report.md").rdbuf();
    return s.str();
  }();
  CHECK(report.find("quick run") != std::string::npos);
  CHECK(report.find("Wilson") != std::string::npos);
  CHECK(report.find("Where the time went") != std::string::npos);
  // The Voronoi section: voro++ judged on the same families, its speed measured with the check's time.
  CHECK(report.find("## Voronoi cells") != std::string::npos);
  // 3 families x 3 seeds, with the linked voro++'s version
  CHECK(report.find("| `voro++` | " + voronoi_peer_version("voro++") + " | 9 |") != std::string::npos);
  CHECK(std::filesystem::exists(o.out / "data" / "voronoi.csv"));
  CHECK(std::filesystem::exists(o.out / "data" / "voronoi_speed.csv"));
  CHECK(r.facts["voronoi"]["saved_pairs"] == r.facts["voronoi"]["failing_pairs"]);
  // Every failing (peer, source) has an input saved, shrunk or with the reason why not.
  CHECK(r.facts["saved_cells"] == r.facts["failing_cells"]);
  // naive without perturbation fails somewhere on these families at n = 48 in 3 seeds;
  // 6 runs a pass do not shrink 48 points, the passes after the first do.
  if (r.facts["failing_cells"].get<std::size_t>() > 0) {
    CHECK(checked > 0);
    CHECK(r.facts["stage_seconds"]["shrink_passes"].size() >= 2);
    CHECK(more_passes > 0);
  }
}

TEST_CASE("shrink_and_save saves every failing input and says what stopped the shrink",
          "[experiments][leaderboard]") {
  TempDir dir;
  // A stand-in helper that refuses every input: any 3D subset still "fails".
  const std::string helper = dir.file("refuse.sh");
  std::ofstream(helper) << "#!/bin/sh\necho 'no thanks' >&2\nexit 3\n";
  std::filesystem::permissions(helper, std::filesystem::perms::owner_all);
  PeerOptions o;
  o.peer_binary = helper;
  o.timeout_s = 30;
  const auto points = experiments::fuzz_family_sources({"uniform"})[0].generate(20, 1);
  const auto failing_case = [&] {
    experiments::PeerCase c;
    c.peer = "cgal";
    c.source = "uniform";
    c.n = points.size();
    c.run = run_peer("cgal", points, o);
    return c;
  };
  experiments::PeerCase c = failing_case();
  REQUIRE(c.run.verdict == Verdict::refused);
  experiments::shrink_and_save(c, points, o, {200, 0}, dir.path().string(), "test");
  CHECK(c.shrunk_minimal);
  CHECK(c.shrunk_points == 4);  // the smallest input that spans a volume
  CHECK(c.shrink_stop.empty());
  CHECK(c.shrunk_verdict == Verdict::refused);
  CHECK(std::filesystem::exists(dir.path() / c.corpus_file));

  c = failing_case();
  c.index = 1;
  experiments::shrink_and_save(c, points, o, {200, 1e-9}, dir.path().string(), "test");
  CHECK(!c.shrunk_minimal);
  CHECK(c.shrink_stop == "time");
  CHECK(c.shrunk_points == points.size());
  CHECK(std::filesystem::exists(dir.path() / c.corpus_file));

  c = failing_case();
  c.index = 2;
  c.run.verdict = Verdict::hung;
  experiments::shrink_and_save(c, points, o, {200, 0}, dir.path().string(), "test");  // no per-try limit for a hang
  CHECK(c.shrink_stop == "hung");
  CHECK(c.shrink_runs == 0);
  CHECK(c.shrunk_points == points.size());
}
