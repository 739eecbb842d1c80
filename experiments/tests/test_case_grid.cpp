// The grid both peer campaigns run (experiments/case_grid.hpp): its order, the inputs
// drawn from the case seeds, the command that reruns a case, the corpus names, the
// shrink tries' limit.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "experiments/case_grid.hpp"
#include "oracle/peers/temp_dir.hpp"

using namespace dtlab;
using namespace dtlab::experiments;
namespace fs = std::filesystem;

namespace {

CaseGrid small_grid() {
  CaseGrid g;
  g.sources = fuzz_family_sources({"uniform", "lattice"});
  g.cases = 3;
  g.min_points = 5;
  g.max_points = 40;
  g.seed = 7;
  return g;
}

}  // namespace

TEST_CASE("case grid: peers x sources x cases in order; only_case keeps one index", "[case_grid]") {
  const std::vector<std::string> peers = {"a", "b"};
  CaseGrid g = small_grid();
  const auto cases = grid_cases(peers, g);
  REQUIRE(cases.size() == 2 * 2 * 3);
  for (std::size_t w = 0; w < cases.size(); ++w) {
    CHECK(*cases[w].peer == peers[w / 6]);
    CHECK(cases[w].source->name == g.sources[(w / 3) % 2].name);
    CHECK(cases[w].index == w % 3);
  }
  // A case's seed depends on the source and index, not on the peer: every peer gets the same inputs.
  CHECK(cases[0].seed == cases[6].seed);
  CHECK(cases[0].seed != cases[1].seed);
  CHECK(cases[0].seed != cases[3].seed);
  g.only_case = 1;
  const auto one = grid_cases(peers, g);
  REQUIRE(one.size() == 4);
  for (const GridCase& c : one) CHECK(c.index == 1);
  CHECK(grid_cases({}, g).empty());
}

TEST_CASE("case grid: inputs are reproducible and sized within [min_points, max_points]", "[case_grid]") {
  const CaseGrid g = small_grid();
  const std::vector<std::string> peers = {"a"};
  const auto cases = grid_cases(peers, g);
  std::set<std::size_t> sizes;
  for (const GridCase& c : cases) {
    const auto p = grid_points(c, g), q = grid_points(c, g);
    CHECK(p == q);
    sizes.insert(p.size());
    if (c.source->name == "uniform") CHECK((p.size() >= g.min_points && p.size() <= g.max_points));
  }
  CHECK(sizes.size() > 1);  // n comes from the case seed
}

TEST_CASE("case grid: rerun command, corpus stem, shrink try limit", "[case_grid]") {
  const CaseGrid g = small_grid();
  CHECK(grid_case_command("qhull", g, "lattice", 2) ==
        "dtlab fuzz --target qhull --family lattice --case 2 --seed 7 --min-points 5 --points 40 --out DIR");
  CHECK(corpus_stem("dtlab:naive", "uniform", 12, 3) == "dtlab_naive-uniform-n12-3");
  CHECK(corpus_stem("dtlab:naive+none", "near_degenerate", 12, 3) == "dtlab_naive+none-near_degenerate-n12-3");
  CHECK(corpus_stem("voro++", "uniform", 12, 3) == "voro++-uniform-n12-3");
  CHECK(corpus_stem("my_peer~2", "uniform", 12, 3) == "my~5Fpeer~7E2-uniform-n12-3");
  CHECK(shrink_try_limit(0.01, 60) == 2);  // 2 s at least
  CHECK(shrink_try_limit(1.5, 60) == 15);  // 10x the original run
  CHECK(shrink_try_limit(100, 60) == 60);  // the time limit at most
  CHECK(shrink_try_limit(0.01, 1) == 1);   // a limit under 2 s is kept
  CHECK_THROWS_AS(fuzz_family_sources({"no-such-family"}), std::invalid_argument);
}

TEST_CASE("case grid: corpus names taken apart", "[case_grid]") {
  const auto name = parse_corpus_name("cgal-dual-elephant-surface-n3000-12.json");
  REQUIRE(name);
  CHECK(name->prefix == "cgal-dual-elephant-surface");
  CHECK(name->index == 12);
  CHECK(parse_corpus_name(corpus_stem("dtlab:exact", "uniform", 48, 0) + ".node")->prefix ==
        corpus_prefix("dtlab:exact", "uniform"));
  for (const char* other :
       {"mine-uniform-n8-0.txt", "mine-uniform-n8-x.node", "mine-uniform-8-0.node", "mine-uniform-n-0.node",
        "-n8-0.node", "uniform-s1-0-naive+sos.node", "mine-uniform-n8-99999999999999999999999.node"})
    CHECK_FALSE(parse_corpus_name(other));
}

TEST_CASE("case grid: peers whose names differ only in : _ + ~ get different corpus names", "[case_grid]") {
  // ':' and '+' were made '_' and 'p', so dtlab:exact's shrunk inputs overwrote
  // dtlab_exact's, a+b's apb's.
  const std::vector<std::string> peers = {"dtlab:exact", "dtlab_exact", "dtlab~3Aexact", "dtlab~5Fexact",
                                          "a+b",         "apb",         "a_b",           "a:b",
                                          "a~2Bb",       "a__b",        "a:_b",          "a_:b"};
  std::set<std::string> prefixes;
  for (const auto& p : peers) prefixes.insert(corpus_prefix(p, "uniform"));
  CHECK(prefixes.size() == peers.size());
  for (const auto& p : peers)
    CHECK(parse_corpus_name(corpus_stem(p, "uniform", 8, 1) + ".node")->prefix == corpus_prefix(p, "uniform"));
}

// small_grid() (uniform and lattice, cases 0..2) writing into a fresh folder whose
// corpus/ exists.
struct GridFolder {
  TempDir dir;
  CaseGrid grid = small_grid();
  fs::path corpus = dir.path() / "corpus";
  GridFolder() {
    grid.out_dir = dir.path().string();
    fs::create_directories(corpus);
  }
};

TEST_CASE("case grid: a run removes its own cases' corpus entries, any size, nothing else", "[case_grid]") {
  GridFolder folder;
  const CaseGrid& g = folder.grid;
  const fs::path& corpus = folder.corpus;
  const std::vector<std::string> ours = {"p-uniform-n5-0.node", "p-uniform-n5-0.json", "p-lattice-n999-2.node"};
  const std::vector<std::string> others = {"p-uniform-n5-3.node", "q-uniform-n5-0.node", "p-cube-n5-0.node",
                                           "p-uniform-n5-0.txt", "notes.json"};
  for (const auto& f : ours) std::ofstream(corpus / f) << "x";
  for (const auto& f : others) std::ofstream(corpus / f) << "x";
  remove_grid_corpus({"p"}, g);
  for (const auto& f : ours) CHECK_FALSE(fs::exists(corpus / f));
  for (const auto& f : others) CHECK(fs::exists(corpus / f));
  // A run of dtlab:exact leaves dtlab_exact's entries (both were dtlab_exact-...).
  const std::string mine = corpus_stem("dtlab:exact", "uniform", 5, 0) + ".node";
  const std::string theirs = corpus_stem("dtlab_exact", "uniform", 5, 0) + ".node";
  for (const auto& f : {mine, theirs}) std::ofstream(corpus / f) << "x";
  remove_grid_corpus({"dtlab:exact"}, g);
  CHECK_FALSE(fs::exists(corpus / mine));
  CHECK(fs::exists(corpus / theirs));
}

TEST_CASE("case grid: a run removes its cases' entries under the names an earlier dtlab gave them", "[case_grid]") {
  GridFolder folder;
  const CaseGrid& g = folder.grid;
  const fs::path& corpus = folder.corpus;
  const auto entry = [&](const std::string& stem, const std::string& peer) {
    std::ofstream(corpus / (stem + ".node")) << "x";
    if (!peer.empty()) std::ofstream(corpus / (stem + ".json")) << nlohmann::json{{"peer", peer}}.dump();
  };
  // Before the one-to-one escape: voro++ as voropp (the Voronoi campaign), my_peer as
  // my_peer (today my~5Fpeer; my_peer is today's name of my:peer).
  entry("voropp-uniform-n9-1", "voro++");
  entry("voro++-lattice-n9-2", "voro++");  // today's name
  entry("my_peer-lattice-n7-0", "my_peer");
  // The old name of a case of another peer, or without a sidecar to say whose: kept.
  entry("my_peer-uniform-n7-0", "my:peer");
  entry("voropp-uniform-n9-2", "");
  entry("voropp-uniform-n9-3", "voro++");  // no case of the grid
  remove_grid_corpus({"voro++", "my_peer"}, g);
  for (const char* gone : {"voropp-uniform-n9-1.node", "voropp-uniform-n9-1.json", "voro++-lattice-n9-2.node",
                           "voro++-lattice-n9-2.json", "my_peer-lattice-n7-0.node", "my_peer-lattice-n7-0.json"})
    CHECK_FALSE(fs::exists(corpus / gone));
  for (const char* kept : {"my_peer-uniform-n7-0.node", "my_peer-uniform-n7-0.json", "voropp-uniform-n9-2.node",
                           "voropp-uniform-n9-3.node"})
    CHECK(fs::exists(corpus / kept));
}
