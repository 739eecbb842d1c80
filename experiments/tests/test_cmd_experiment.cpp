// The experiment command: usage errors, and a tiny benchmark end to end.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

namespace dtlab::cli {
void add_experiment_command(CLI::App& app, int& rc);
}

namespace {

int run_cli(std::vector<std::string> args) {
  CLI::App app("dtlab");
  app.require_subcommand(1);
  int rc = 0;
  dtlab::cli::add_experiment_command(app, rc);
  std::vector<const char*> argv = {"dtlab"};
  for (auto& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError&) {
    return 2;
  }
  return rc;
}

}  // namespace

TEST_CASE("dtlab experiment: usage errors give exit code 2", "[experiments]") {
  CHECK(run_cli({"experiment"}) == 2);
  CHECK(run_cli({"experiment", "nothing"}) == 2);
  CHECK(run_cli({"experiment", "benchmark", "--runs", "0"}) == 2);
}

TEST_CASE("dtlab experiment benchmark at n = 1000 writes its report", "[experiments]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("dtlab_bench_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  CHECK(run_cli({"experiment", "benchmark", "--quick", "--out", dir.string(), "--max-n", "1000", "--runs", "2",
                 "--no-figures"}) == 0);
  for (const char* f : {"report.md", "report.html", "data/summary.csv", "data/runs.csv", "data/results.json"})
    CHECK(fs::exists(dir / f));
  std::ifstream in(dir / "data" / "results.json");
  const auto j = nlohmann::json::parse(in);
  int dtlab_rows = 0;
  for (const auto& r : j["summary"])
    if (r["tool"] == "dtlab") {
      ++dtlab_rows;
      CHECK(r["ok"].get<bool>());
      CHECK(r["tets"].get<int>() > 1000);
    }
  CHECK(dtlab_rows == 4);  // uniform, clustered, lattice, torus-winding at n = 1000
  CHECK(j["predicates"].size() == 16);
  // the near-degenerate tuples really are hard for the filter: most adaptive calls go past it
  for (const auto& r : j["predicates"])
    if (r["backend"] == "adaptive") {
      INFO(r.dump());
      const double filter = r["stages"].value("semistatic", 0.0) / r["calls"].get<double>();
      if (r["points"] == "near_degenerate") CHECK(filter < 0.5);
      if (r["points"] == "uniform") CHECK(filter > 0.9);
    }
  std::ifstream md_in(dir / "report.md");
  const std::string md((std::istreambuf_iterator<char>(md_in)), std::istreambuf_iterator<char>());
  CHECK(md.find("**Quick run**") != std::string::npos);
  CHECK(md.find("## Findings") != std::string::npos);
  CHECK(md.find("dtlab vs CGAL") != std::string::npos);
  fs::remove_all(dir);
}
