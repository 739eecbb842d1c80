// The campaign summary: Wilson intervals, independence of record order and shards,
// merging folders, and the files a campaign folder holds.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>

#include "dtlab/build_info.hpp"
#include "fuzz/campaign.hpp"
#include "fuzz/campaign_report.hpp"
#include "fuzz/rate_interval.hpp"
#include "fuzz/summary.hpp"
#include "fuzz/tests/test_folder.hpp"

using namespace dtlab;
using namespace dtlab::fuzz;
namespace fs = std::filesystem;

namespace {

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

CampaignOptions small_campaign(const fs::path& out) {
  CampaignOptions o;
  o.families = {"uniform", "near_degenerate", "kettner_grid"};
  o.cases = 6;
  o.max_points = 24;
  o.backends.resize(2);
  o.backends[0].backend = "naive";
  o.backends[0].perturb = false;
  o.backends[1].backend = "adaptive";
  o.shrink = false;
  o.out_dir = out.string();
  return o;
}

}  // namespace

TEST_CASE("Wilson interval: known values, bounds and degenerate counts", "[fuzz][summary]") {
  const RateInterval none = wilson_interval(0, 10);
  CHECK(none.rate == 0);
  CHECK(none.low == 0);
  CHECK(none.high == Approx(0.2775).margin(1e-4));
  const RateInterval half = wilson_interval(5, 10);
  CHECK(half.low == Approx(0.2366).margin(1e-4));
  CHECK(half.high == Approx(0.7634).margin(1e-4));
  const RateInterval all = wilson_interval(64, 64);
  CHECK(all.high == 1);
  CHECK(all.low == Approx(0.9434).margin(1e-4));
  const RateInterval empty = wilson_interval(0, 0);
  CHECK((empty.low == 0 && empty.high == 1));
  for (std::size_t n : {1, 7, 64, 1000})
    for (std::size_t k = 0; k <= n; k += std::max<std::size_t>(1, n / 7)) {
      const RateInterval r = wilson_interval(k, n);
      CHECK(0 <= r.low);
      CHECK(r.low <= r.rate);
      CHECK(r.rate <= r.high);
      CHECK(r.high <= 1);
    }
  CHECK(rate_text(wilson_interval(5, 10)) == "50.0% [23.7, 76.3] (5/10)");
}

TEST_CASE("campaign folder: summary and environment files, lines carry the build", "[fuzz][summary]") {
  TestFolder dir;
  const CampaignResult r = run_campaign(small_campaign(dir.path));
  REQUIRE(r.failing() > 0);  // naive fails on kettner_grid: the summary is not trivial
  for (const char* f : {"summary.md", "summary.json", "environment.json", "results.jsonl"})
    CHECK(fs::exists(dir.path / f));
  const auto summary = nlohmann::json::parse(read_file(dir.path / "summary.json"));
  CHECK(summary["cases"] == r.records.size());
  CHECK(summary["failing"] == r.failing());
  CHECK(summary["builds"][0] == std::string(build_version()) + " " + build_commit());
  for (const auto& cell : summary["cells"]) {
    const RateInterval w = wilson_interval(cell["failures"], cell["cases"]);
    CHECK(cell["ci95"][0].get<double>() == w.low);
    CHECK(cell["ci95"][1].get<double>() == w.high);
    std::size_t kinds = 0;
    for (const auto& [k, v] : cell["failure_kinds"].items()) kinds += v.get<std::size_t>();
    CHECK(kinds == cell["failures"].get<std::size_t>());
    CHECK(!cell.contains("build_s"));  // no timings: the file depends on the results only
  }
  const auto env = nlohmann::json::parse(read_file(dir.path / "environment.json"));
  REQUIRE(env["runs"].size() == 1);
  CHECK(env["runs"][0]["build"]["git_commit"] == build_commit());
  CHECK(env["runs"][0]["campaign"]["seed"] == 1);
  CHECK(!env["runs"][0]["machine"]["cpu"].get<std::string>().empty());
  for (const auto& rec : read_records(dir.path.string())) {
    CHECK(rec.version == build_version());
    CHECK(rec.commit == build_commit());
  }
  // the markdown summary renders every cell's rate with its interval
  const std::string md = read_file(dir.path / "summary.md");
  for (const auto& cell : summary["cells"])
    CHECK(md.find(rate_text(wilson_interval(cell["failures"], cell["cases"]))) != std::string::npos);
}

TEST_CASE("summary: shards merged from separate folders equal the unsharded run", "[fuzz][summary]") {
  TestFolder whole, s0, s1, merged;
  run_campaign(small_campaign(whole.path));
  for (int k = 0; k < 2; ++k) {
    CampaignOptions o = small_campaign(k == 0 ? s0.path : s1.path);
    o.shard = static_cast<unsigned>(k);
    o.shards = 2;
    o.jobs = 2;
    run_campaign(o);
  }
  CHECK(!fs::exists(s0.path / "summary.json"));  // a shard writes no summary of its own
  // s0 listed twice: a (case, backend) counts once
  const auto records = read_campaigns({s0.path.string(), s1.path.string(), s0.path.string()});
  fs::create_directories(merged.path);
  write_summary_files(merged.path.string(), summarize(records));
  CHECK(read_file(merged.path / "summary.json") == read_file(whole.path / "summary.json"));
  CHECK(read_file(merged.path / "summary.md") == read_file(whole.path / "summary.md"));
  // and the record order does not matter
  auto shuffled = records;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
  CHECK(summary_markdown(summarize(shuffled)) == read_file(whole.path / "summary.md"));
  const auto envs = read_environments({s0.path.string(), s1.path.string()});
  CHECK(envs.size() == 2);
}
