#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "fuzz/campaign.hpp"
#include "fuzz/corpus.hpp"
#include "fuzz/families.hpp"
#include "fuzz/summary.hpp"
#include "fuzz/tests/test_folder.hpp"
#include "kernel/input_error.hpp"

using namespace dtlab;
using namespace dtlab::fuzz;
namespace fs = std::filesystem;

namespace {

PredicateSpec spec(const std::string& backend, bool perturb) {
  PredicateSpec s;
  s.backend = backend;
  s.perturb = perturb;
  return s;
}

std::vector<std::string> all_families() {
  std::vector<std::string> names;
  for (const auto& f : families()) names.push_back(f.name);
  return names;
}

}  // namespace

TEST_CASE("is_lower_dimensional decides flatness exactly", "[fuzz][campaign]") {
  CHECK(is_lower_dimensional(std::vector<Point3>{}));
  CHECK(is_lower_dimensional(std::vector<Point3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  CHECK(is_lower_dimensional(find_family("coplanar_all")->generate(50, 3)));
  CHECK_FALSE(is_lower_dimensional(find_family("coplanar_slabs")->generate(50, 3)));
  CHECK_FALSE(is_lower_dimensional(find_family("cospherical")->generate(50, 3)));
  // Collinear, with repeats, then one point off the line: still flat.
  std::vector<Point3> line = {{0, 0, 0}, {0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {0, 1, 0}};
  CHECK(is_lower_dimensional(line));
  line.push_back({0, 0, 1});
  CHECK_FALSE(is_lower_dimensional(line));
  // Off the plane by one ulp.
  std::vector<Point3> flat = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  CHECK(is_lower_dimensional(flat));
  flat[3].z = 0x1p-1074;
  CHECK_FALSE(is_lower_dimensional(flat));
}

TEST_CASE("boundary labels parse and print", "[fuzz][campaign]") {
  BuildOptions b;
  CHECK(parse_boundary("infinite", b));
  CHECK(boundary_label(b) == "infinite");
  CHECK(parse_boundary("bigtet:2.5", b));
  CHECK(boundary_label(b) == "bigtet:2.5");
  CHECK(parse_boundary("bigtet", b));
  CHECK_FALSE(parse_boundary("bigtet:", b));
  CHECK_FALSE(parse_boundary("bigtet:x", b));
  CHECK_FALSE(parse_boundary("ghost", b));
}

TEST_CASE("a tiny campaign with robust backends finds no defect on any family",
          "[fuzz][campaign]") {
  TestFolder dir;
  CampaignOptions o;
  o.families = all_families();
  o.cases = 3;
  o.min_points = 5;
  o.max_points = 24;
  o.seed = 11;
  o.backends = {spec("adaptive", true), spec("exact", true), spec("exact", false)};
  o.jobs = 2;
  o.out_dir = dir.path.string();
  const CampaignResult r = run_campaign(o);
  CHECK(r.ran == o.families.size() * o.cases);
  REQUIRE(r.records.size() == r.ran * o.backends.size());
  for (const auto& rec : r.records) {
    INFO(rec.id << " " << rec.backend << ": " << rec.run.outcome << " " << rec.run.detail);
    CHECK(rec.run.ok());
  }
  CHECK(r.failing() == 0);
  CHECK_FALSE(fs::exists(dir.path / "corpus"));
}

TEST_CASE("campaigns are deterministic, resumable and shardable", "[fuzz][campaign]") {
  TestFolder a, b;
  CampaignOptions o;
  o.families = {"uniform", "lattice", "cospherical"};
  o.cases = 4;
  o.max_points = 20;
  o.backends = {spec("exact", true)};
  o.out_dir = a.path.string();
  o.jobs = 2;
  const CampaignResult first = run_campaign(o);
  REQUIRE(first.ran == 12);

  // Resumed: nothing left to do.
  const CampaignResult again = run_campaign(o);
  CHECK(again.ran == 0);
  CHECK(again.resumed == 12);
  CHECK(again.records.size() == 12);

  // Two shards into another folder give the same cases with the same outcomes.
  o.out_dir = b.path.string();
  o.shards = 2;
  o.jobs = 1;
  o.shard = 0;
  const CampaignResult s0 = run_campaign(o);
  o.shard = 1;
  const CampaignResult s1 = run_campaign(o);
  CHECK(s0.ran + s1.ran == 12);
  CHECK(s0.ran == 6);
  const auto key = [](const CaseRecord& r) {
    return r.id + "|" + std::to_string(r.case_seed) + "|" + std::to_string(r.points) + "|" +
           r.run.outcome + "|" + std::to_string(r.run.tets);
  };
  std::set<std::string> ka, kb;
  for (const auto& r : read_records(a.path.string())) ka.insert(key(r));
  for (const auto& r : read_records(b.path.string())) kb.insert(key(r));
  CHECK(ka.size() == 12);
  CHECK(ka == kb);
}

TEST_CASE("naive predicates fail on near-degenerate inputs, and failures shrink to a replayable corpus",
          "[fuzz][campaign]") {
  TestFolder dir;
  CampaignOptions o;
  o.families = {"near_degenerate", "kettner_grid", "extreme_scale", "subnormal"};
  o.cases = 6;
  o.min_points = 16;
  o.max_points = 48;
  o.seed = 3;
  o.backends = {spec("naive", false)};
  o.jobs = 2;
  o.shrink_budget = 300;
  o.out_dir = dir.path.string();
  const CampaignResult r = run_campaign(o);
  REQUIRE(r.failing() > 0);
  std::size_t shrunk = 0;
  for (const auto& rec : r.records) {
    if (rec.run.ok()) continue;
    REQUIRE(rec.shrunk_points > 0);
    CHECK(rec.shrunk_points <= rec.points);
    shrunk += rec.shrunk_points < rec.points;
    CHECK(fs::exists(dir.path / rec.corpus_file));
  }
  CHECK(shrunk > 0);
  // Replaying the corpus reproduces each recorded outcome.
  const auto replayed = replay_corpus(dir.path.string(), {});
  REQUIRE(replayed.size() == r.failing());
  for (const auto& p : replayed) {
    INFO(p.file);
    CHECK(p.run.outcome == p.recorded_outcome);
  }
  // The summary lists every family that ran.
  const std::string table = summary_table(summarize(r.records));
  for (const auto& f : o.families) CHECK(table.find(f) != std::string::npos);
  // Each shrunk failure of naive is handled by the robust backends.
  ReplayOptions robust;
  robust.backends = {spec("adaptive", true), spec("exact", true)};
  for (const auto& p : replay_corpus(dir.path.string(), robust)) {
    INFO(p.file << " " << p.backend << ": " << p.run.outcome << " " << p.run.detail);
    CHECK(p.run.ok());
  }
}

TEST_CASE("the committed corpus replays cleanly with robust backends", "[fuzz][campaign]") {
  const fs::path corpus = fs::path(DTLAB_SOURCE_DIR) / "fuzz" / "corpus";
  REQUIRE(fs::is_directory(corpus));
  ReplayOptions robust;
  robust.backends = {spec("adaptive", true), spec("exact", true), spec("exact", false)};
  const auto results = replay_corpus(corpus.string(), robust);
  CHECK(!results.empty());
  for (const auto& p : results) {
    INFO(p.file << " " << p.backend << ": " << p.run.outcome << " " << p.run.detail);
    CHECK(p.run.ok());
  }
}

TEST_CASE("a corpus sidecar that is wrong is refused with its file and line", "[fuzz][campaign]") {
  TestFolder dir;
  fs::create_directories(dir.path);
  {
    std::ofstream node(dir.path / "c.node");
    node << "5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 0.3 0.3 0.3\n";
  }
  const auto refusal = [&](const std::string& sidecar) -> std::string {
    std::ofstream(dir.path / "c.json") << sidecar;
    try {
      replay_corpus((dir.path / "c.node").string(), {});
    } catch (const InputError& e) {
      return std::to_string(e.line()) + ":" + e.reason();
    }
    return "accepted";
  };
  // An unknown backend was run and graded a failing case (exit 1), not bad input.
  CHECK(
      refusal("{\n  \"outcome\": \"ok\",\n  \"predicates\": \"bogus\"\n}\n").rfind("3:unknown predicates 'bogus'", 0) ==
      0);
  // JSON errors name their line, not line 0.
  CHECK(refusal("{\n  \"outcome\": \"ok\",\n  \"predicates\": \n").rfind("4:", 0) == 0);
  CHECK(refusal("{\n  \"outcome\": \"ok\",\n  \"case_seed\": \"x\"\n}\n").rfind("3:'case_seed'", 0) == 0);
  CHECK(refusal("{\n  \"boundary\": \"moon\"\n}\n") == "2:bad boundary 'moon'");
  CHECK(refusal("[1, 2]\n") == "1:expected a JSON object");
  CHECK(refusal("{\"predicates\": \"exact\"}\n") == "accepted");
  // The order and the thread count the entry's campaign built with: out of range, refused.
  CHECK(refusal("{\n  \"order\": \"hilbert\"\n}\n") == "2:bad order 'hilbert' (expected brio or input)");
  CHECK(refusal("{\n  \"order\": 1\n}\n").rfind("2:'order'", 0) == 0);
  for (const char* bad : {"0", "-1", "1025", "2.5", "\"2\"", "null", "18446744073709551615"}) {
    INFO(bad);
    CHECK(refusal(std::string("{\n  \"outcome\": \"ok\",\n  \"threads\": ") + bad + "\n}\n")
              .rfind(std::string("3:bad threads ") + bad + " (expected 1 to 1024", 0) == 0);
  }
  CHECK(refusal("{\"threads\": 1024, \"order\": \"input\"}\n") == "accepted");
  // The epsilon band the entry's campaign ran with.
  CHECK(refusal("{\n  \"eps\": -1\n}\n") == "2:bad eps -1 (expected a positive number)");
  CHECK(refusal("{\n  \"eps_mode\": \"loose\"\n}\n") == "2:bad eps_mode \"loose\" (expected absolute or relative)");
  CHECK(refusal("{\"predicates\": \"epsilon\", \"eps\": 1e-6, \"eps_mode\": \"relative\"}\n") == "accepted");
  CHECK(refusal("{\"predicates\": \"exact\", \"eps\": null, \"eps_mode\": null}\n") == "accepted");
  // The oracles it was compared with: a list of names, else refused.
  CHECK(refusal("{\n  \"against\": \"cgal\"\n}\n") == "2:bad against \"cgal\" (expected a list of oracle names)");
  CHECK(refusal("{\n  \"against\": [\"\"]\n}\n").rfind("2:bad against", 0) == 0);
  CHECK(refusal("{\"against\": []}\n") == "accepted");
  // A field named twice: refused, not the last one kept.
  CHECK(refusal("{\n  \"threads\": 2,\n  \"threads\": 1\n}\n") == "2:duplicate field 'threads'");
  // The refusal names the sidecar.
  std::ofstream(dir.path / "c.json") << "{\"threads\": 0}\n";
  try {
    replay_corpus((dir.path / "c.node").string(), {});
    FAIL("a sidecar with threads 0 was accepted");
  } catch (const InputError& e) {
    CHECK(e.file() == (dir.path / "c.json").string());
  }
}

namespace {

// A corpus entry "e.node" of 40 uniform points in `dir`, with the sidecar `sidecar` (none: "").
fs::path corpus_entry(const fs::path& dir, const std::string& sidecar) {
  fs::create_directories(dir);
  std::ofstream node(dir / "e.node");
  const auto points = find_family("uniform")->generate(40, 5);
  node.precision(17);
  node << points.size() << " 3 0 0\n";
  for (std::size_t i = 0; i < points.size(); ++i)
    node << i << " " << points[i].x << " " << points[i].y << " " << points[i].z << "\n";
  if (!sidecar.empty()) std::ofstream(dir / "e.json") << sidecar;
  return dir / "e.node";
}

}  // namespace

TEST_CASE("a corpus entry is replayed with the threads and order of its sidecar", "[fuzz][campaign][replay]") {
  TestFolder dir;
  SECTION("threads 2: the campaign's threaded build (every case split across the threads)") {
    const fs::path node = corpus_entry(dir.path, R"({"predicates": "adaptive", "perturb": "sos", "outcome": "valid",
                                                      "case_seed": 7, "order": "input", "threads": 2})");
    const auto results = replay_corpus(node.string(), {});
    REQUIRE(results.size() == 1);
    CHECK(results[0].threads == 2);
    CHECK(results[0].order == "input");
    CHECK(results[0].run.outcome == "valid");
    // parallel_grain 1 as in the campaign: 40 points do run passes on the threads (the
    // default grain, 2048 points a thread, would insert them serially).
    CHECK(results[0].run.parallel_passes > 0);
    // --threads 1 and --order given to the replay override the sidecar.
    ReplayOptions serial;
    serial.threads = 1;
    serial.order = InsertionOrder::brio;
    const auto overridden = replay_corpus(node.string(), serial);
    REQUIRE(overridden.size() == 1);
    CHECK(overridden[0].threads == 1);
    CHECK(overridden[0].order == "brio");
    CHECK(overridden[0].run.parallel_passes == 0);
    // --boundary overrides the boundary alone: the recorded threads and order stay.
    ReplayOptions bigtet;
    bigtet.boundary = BuildOptions{};
    bigtet.boundary->boundary = Boundary::bigtet;
    const auto boxed = replay_corpus(node.string(), bigtet);
    REQUIRE(boxed.size() == 1);
    CHECK(boxed[0].boundary == "bigtet:10");
    CHECK(boxed[0].threads == 2);
    CHECK(boxed[0].order == "input");
    CHECK(boxed[0].run.parallel_passes > 0);
  }
  SECTION("a sidecar from before order and threads were kept: brio, serial") {
    const fs::path node = corpus_entry(dir.path, R"({"predicates": "adaptive", "perturb": "sos", "outcome": "valid",
                                                      "case_seed": 7})");
    const auto results = replay_corpus(node.string(), {});
    REQUIRE(results.size() == 1);
    CHECK(results[0].threads == 1);
    CHECK(results[0].order == "brio");
    CHECK(results[0].run.outcome == "valid");
    CHECK(results[0].run.parallel_passes == 0);
  }
  SECTION("no sidecar: brio, serial") {
    const auto results = replay_corpus(corpus_entry(dir.path, "").string(), {});
    REQUIRE(results.size() == 1);
    CHECK(results[0].threads == 1);
    CHECK(results[0].order == "brio");
    CHECK(results[0].run.parallel_passes == 0);
  }
}

TEST_CASE("a threaded campaign's corpus records its threads and order and replays with them",
          "[fuzz][campaign][replay]") {
  TestFolder dir;
  CampaignOptions o;
  o.families = {"near_degenerate", "kettner_grid"};
  o.cases = 3;
  o.min_points = 16;
  o.max_points = 40;
  o.seed = 3;
  o.backends = {spec("naive", false), PredicateSpec{"epsilon", 1e-3, true, false}};
  o.build.threads = 2;
  o.build.parallel_grain = 1;  // as dtlab fuzz --threads 2 sets it (use_build_threads)
  o.build.order = InsertionOrder::input;
  o.jobs = 2;
  o.shrink_budget = 100;
  o.out_dir = dir.path.string();
  const CampaignResult r = run_campaign(o);
  REQUIRE(r.failing() > 0);
  std::size_t entries = 0, epsilon_entries = 0;
  for (const auto& rec : r.records) {
    if (rec.run.ok()) continue;
    ++entries;
    std::ifstream in(dir.path / (rec.corpus_file.substr(0, rec.corpus_file.size() - 5) + ".json"));
    const auto j = nlohmann::json::parse(in);
    CHECK(j.at("threads") == 2);
    CHECK(j.at("order") == "input");
    // The epsilon band goes with an epsilon entry (it replayed at the default 1e-12 before).
    if (rec.predicates == "epsilon") {
      ++epsilon_entries;
      CHECK(j.at("eps") == 1e-3);
      CHECK(j.at("eps_mode") == "relative");
    } else {
      CHECK(j.at("eps").is_null());
    }
  }
  CHECK(epsilon_entries > 0);
  const auto replayed = replay_corpus(dir.path.string(), {});
  REQUIRE(replayed.size() == entries);
  for (const auto& p : replayed) {
    INFO(p.file);
    CHECK(p.threads == 2);
    CHECK(p.order == "input");
  }
}

TEST_CASE("a corpus entry that differed from an oracle is compared with it again when replayed",
          "[fuzz][campaign][replay]") {
  // An oracle that disagrees with every build of 9 or more points: the shrinker keeps 9.
  const auto picky = [](const std::string& name) {
    return OracleHook{name, [](std::span<const Point3> points, const BuildResult&) -> std::string {
                        return points.size() >= 9 ? "too-many" : "";
                      }};
  };
  TestFolder dir;
  CampaignOptions o;
  o.families = {"uniform"};
  o.cases = 2;
  o.min_points = 12;
  o.max_points = 20;
  o.backends = {spec("adaptive", true)};
  o.oracles = {picky("picky")};
  o.out_dir = dir.path.string();
  const CampaignResult r = run_campaign(o);
  REQUIRE(r.failing() == 2);
  for (const auto& rec : r.records) {
    CHECK(rec.run.outcome == "oracle-picky");
    std::ifstream in(dir.path / (rec.corpus_file.substr(0, rec.corpus_file.size() - 5) + ".json"));
    const auto j = nlohmann::json::parse(in);
    CHECK(j.at("against") == nlohmann::json::array({"picky"}));
    CHECK(j.at("reproduce_original").get<std::string>().find(" --against picky ") != std::string::npos);
  }
  std::vector<std::string> asked;
  ReplayOptions replay;
  replay.oracles = [&](const std::vector<std::string>& names, const PredicateSpec&, const BuildOptions&) {
    asked.insert(asked.end(), names.begin(), names.end());
    std::vector<OracleHook> hooks;
    for (const auto& n : names) hooks.push_back(picky(n));
    return hooks;
  };
  const auto replayed = replay_corpus(dir.path.string(), replay);
  REQUIRE(replayed.size() == 2);
  CHECK(asked == std::vector<std::string>{"picky", "picky"});
  for (const auto& p : replayed) {
    INFO(p.file);
    CHECK(p.against == std::vector<std::string>{"picky"});
    CHECK(p.run.outcome == "oracle-picky");  // the build alone is valid: before, the replay said so
    CHECK(p.recorded_outcome == "oracle-picky");
  }
  // --against none given to the replay: the build alone, valid.
  replay.against.emplace();
  for (const auto& p : replay_corpus(dir.path.string(), replay)) CHECK(p.run.outcome == "valid");
  // Without hooks to run, the recorded oracles cannot be compared: refused, not passed.
  CHECK_THROWS_AS(replay_corpus(dir.path.string(), {}), std::invalid_argument);
}
