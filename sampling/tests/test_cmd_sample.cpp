// The `dtlab sample` command, driven through its own CLI11 app (the lead wires it
// into the real one).
#include <catch2/catch.hpp>

#include <CLI/CLI.hpp>

#include "cli/command.hpp"
#include "kernel/point_io.hpp"
#include "scratch.hpp"

namespace dtlab::cli {
void add_sample_command(CLI::App& app, int& rc);
}

using namespace dtlab;

namespace {
int run_cli(std::vector<std::string> args) {
  CLI::App app{"test"};
  int rc = 0;
  cli::add_sample_command(app, rc);
  std::vector<const char*> argv{"dtlab"};
  for (auto& a : args) argv.push_back(a.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
  return rc;
}
}  // namespace

TEST_CASE("dtlab sample writes the requested points") {
  const std::string out = test::scratch("cmd.xyz").string();
  CHECK(run_cli({"sample", "builtin", "--method", "winding", "--count", "200", "--seed", "3", "--out", out, "--json"}) == 0);
  CHECK(read_xyz(out).points.size() == 200);
  CHECK(run_cli({"sample", "builtin", "--method", "surface", "--count", "50", "--blue-noise", "--out", out}) == 0);
  CHECK(read_xyz(out).points.size() == 50);
}

TEST_CASE("dtlab sample reports bad input as file:line") {
  const std::string mesh = test::write_file("cmd_bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n");
  const std::string out = test::scratch("cmd_bad.xyz").string();
  CHECK(test::input_error([&] { run_cli({"sample", mesh, "--out", out}); }) ==
        "6:vertex index 5 out of range (mesh has 3 vertices)");
  CHECK_THROWS_AS(run_cli({"sample", "builtin", "--method", "magic", "--out", out}), CLI::ValidationError);
}
