// thesis-failures --quick into a temporary folder: the report is complete and the
// facts the thesis reports hold when measured.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "experiments/thesis_failures.hpp"

namespace fs = std::filesystem;
using dtlab::experiments::ExperimentResult;

namespace {

const fs::path& report_dir() {
  static const fs::path dir = fs::temp_directory_path() / ("dtlab_thesis_" + std::to_string(::getpid()));
  return dir;
}

const ExperimentResult& quick_run() {
  static const ExperimentResult r = [] {
    fs::remove_all(report_dir());
    // DTLAB_KEEP_REPORT=1 keeps the folder for a look at the figures
    if (!std::getenv("DTLAB_KEEP_REPORT")) std::atexit([] { fs::remove_all(report_dir()); });
    dtlab::experiments::ThesisFailuresOptions o;
    o.out = report_dir();
    o.quick = true;
    o.command_line = "dtlab experiment thesis-failures --quick";
    return dtlab::experiments::run_thesis_failures(o);
  }();
  return r;
}

bool have_matplotlib() {
  return std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

}  // namespace

TEST_CASE("thesis-failures --quick writes a self-contained report", "[experiments]") {
  const auto& r = quick_run();
  CHECK(r.exit_code == 0);
  for (const char* f : {"report.md", "report.html", "environment.json", "commands.sh", "data/rates.csv",
                        "data/epsilon.csv", "data/bigtet.csv", "data/cost.csv", "data/sampling.csv",
                        "data/results.json", "data/facts.json", "data/overlap_case.json", "data/overlap_case.xyz"})
    CHECK(fs::exists(report_dir() / f));
  std::ifstream md(report_dir() / "report.md");
  const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
  CHECK(text.find("model name") == std::string::npos);  // the value, not the raw field
  CHECK(text.find("| CPU |") != std::string::npos);
  CHECK(text.find("dtlab experiment thesis-failures --quick") != std::string::npos);
  CHECK(text.find("**Quick run**") != std::string::npos);  // a small run says so
  // every Findings bullet carries a number, and its rates carry interval and counts
  const auto findings = text.substr(text.find("## Findings"), text.find("## 1.") - text.find("## Findings"));
  std::size_t bullets = 0;
  for (std::size_t at = findings.find("\n- "); at != std::string::npos; at = findings.find("\n- ", at + 1)) {
    const std::string bullet = findings.substr(at, findings.find('\n', at + 1) - at);
    INFO(bullet);
    CHECK(bullet.find_first_of("0123456789") != std::string::npos);
    if (bullet.find('%') != std::string::npos) CHECK(bullet.find("% [") != std::string::npos);
    ++bullets;
  }
  CHECK(bullets == 5);
  CHECK(text.find("commit `") != std::string::npos);  // the report names its build
  std::ifstream html_in(report_dir() / "report.html");
  const std::string html((std::istreambuf_iterator<char>(html_in)), std::istreambuf_iterator<char>());
  if (have_matplotlib()) {
    CHECK(html.find("<em>Failure rate vs n") != std::string::npos);
    CHECK(html.find("<p>*") == std::string::npos);
  }
  if (have_matplotlib()) {
    CHECK(r.facts.value("figures_status", -1) == 0);
    for (const char* f : {"fig_rates.png", "fig_naive_kinds.png", "fig_epsilon.png", "fig_bigtet.png", "fig_cost.png",
                          "fig_sampling.png", "fig_sampling_slice.png", "fig_overlap.png"})
      CHECK(fs::exists(report_dir() / f));
  }
}

TEST_CASE("thesis-failures: naive fails on near-degenerate input, adaptive and exact never", "[experiments]") {
  const auto& f = quick_run().facts;
  CHECK(f["naive_failure_rate_hard_at_max_n"].get<double>() > 0);
  CHECK(f["naive_cases_with"]["failed"].get<int>() > 0);
  CHECK(f["robust_failed_cases"]["adaptive+sos"].get<int>() == 0);
  CHECK(f["robust_failed_cases"]["exact+sos"].get<int>() == 0);
  CHECK(f["robust_defects_in_cost_runs"].get<int>() == 0);
  CHECK(f["overlap_case_points"].get<int>() >= 4);
}

TEST_CASE("thesis-failures: epsilon does not fix it, bigtet misses tets, rays leak", "[experiments]") {
  const auto& f = quick_run().facts;
  CHECK(f["epsilon_best_failure_rate"]["absolute"]["rate"].get<double>() > 0);
  CHECK(f["epsilon_best_failure_rate"]["relative"]["rate"].get<double>() > 0);
  CHECK(f["bigtet_cases_wrong_at_smallest_factor"].get<int>() > 0);
  CHECK(f["outside_fraction"]["rays"]["20"].get<double>() > 0.01);
  CHECK(f["outside_fraction"]["winding"]["20"].get<double>() < f["outside_fraction"]["rays"]["20"].get<double>());
  CHECK(f["outside_fraction"]["winding"]["0"].get<double>() == 0);
}
