// dtlab demo: the whole pipeline on the built-in bumpy torus, as the sequence of
// dtlab commands a user would type (each printed before it runs).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_error.hpp"
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/commands.hpp"
#include "cli/stdout_to_stderr.hpp"

#ifndef DTLAB_SOURCE_DIR
#define DTLAB_SOURCE_DIR "."
#endif

namespace dtlab::cli {

namespace {

struct DemoArgs {
  std::string out = "out/demo";
  std::size_t points = 20000;
  std::size_t pieces = 30;
  bool no_oracles = false;
  bool json = false;
};

// Runs `dtlab args...` in this process, through the same parser as the shell.
int run_dtlab(std::vector<std::string> args) {
  std::string line = "$ dtlab";
  for (const auto& a : args) line += " " + a;
  std::printf("\n%s\n", line.c_str());
  std::fflush(stdout);
  CLI::App app{"dtlab", "dtlab"};
  app.require_subcommand(1);
  int rc = kOk;
  register_commands(app, rc);
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError&) {
    return report_error(current_error(args.empty() ? "" : args.front()), false);
  }
  std::fflush(stdout);
  return rc;
}

int run_steps(const DemoArgs& a, nlohmann::json& summary) {
  namespace fs = std::filesystem;
  fs::create_directories(a.out);
  const std::string o = a.out;
  std::printf("dtlab demo: sample the built-in bumpy torus, tetrahedralize, check exactly,\n"
              "compare with CGAL and TetGen, extract Voronoi cells, fracture the mesh.\n"
              "Output folder: %s\n", o.c_str());
  struct Step {
    std::vector<std::string> args;
    const char* what;
  };
  std::vector<Step> steps = {
      {{"sample", "builtin", "--method", "winding", "--count", std::to_string(a.points), "--seed", "1", "--out", o + "/torus_points.xyz"},
       "points inside the torus (fast winding numbers)"},
      {{"tetra", o + "/torus_points.xyz", "--out", o + "/torus_dt", "--vtu"}, "Delaunay tetrahedralization (adaptive + sos)"},
      {{"check", o + "/torus_dt"}, "exact invariant check"},
  };
  if (!a.no_oracles)
    steps.push_back({{"oracle", o + "/torus_points.xyz", "--against", "cgal,tetgen"}, "CGAL and TetGen oracles"});
  steps.push_back({{"voronoi", o + "/torus_points.xyz", "--out", o + "/voronoi", "--check"}, "Voronoi cells clipped to a box"});
  steps.push_back({{"sample", "builtin", "--method", "winding", "--count", "40", "--seed", "2", "--out", o + "/cells_points.xyz"},
                   "a few dozen sites, for a picture of their cells"});
  steps.push_back({{"voronoi", o + "/cells_points.xyz", "--margin", "0.02", "--out", o + "/cells", "--vtu", "--check", "--png",
                    o + "/voronoi_cells.png"},
                   "their Voronoi cells, drawn shrunk (binary VTU for ParaView)"});
  steps.push_back({{"fracture", "builtin", "--pieces", std::to_string(a.pieces), "--seed", "1", "--out", o + "/fracture"},
                   "Voronoi fracture of the torus"});
  for (const Step& s : steps) {
    const int rc = run_dtlab(s.args);
    std::string command = "dtlab";
    for (const auto& arg : s.args) command += " " + arg;
    summary["steps"].push_back({{"what", s.what}, {"command", command}, {"exit", rc}});
    if (rc != kOk) {
      std::fprintf(stderr, "dtlab demo: step '%s' failed (exit %d)\n", s.what, rc);
      return rc;
    }
  }
  // The picture of the exploded pieces: matplotlib, headless.
  const std::string script = std::string(DTLAB_SOURCE_DIR) + "/fracture/render_pieces.py";
  const std::string png = o + "/fracture/exploded.png";
  const std::string cmd = "/usr/bin/python3 '" + script + "' '" + o + "/fracture/exploded.obj' '" + png + "'";
  std::printf("\n$ %s\n", cmd.c_str());
  std::fflush(stdout);
  if (std::system(cmd.c_str()) != 0)  // reported by main() (cli/cli_error.hpp), exit 2
    throw std::runtime_error("rendering the picture failed (is python3-matplotlib installed?)");
  summary["picture"] = png;
  summary["cells_picture"] = o + "/voronoi_cells.png";
  summary["tetrahedralization"] = o + "/torus_dt";
  std::printf("\ndtlab demo: done. Look at %s (exploded pieces) and %s/voronoi_cells.png (Voronoi cells),\n"
              "open %s/torus_dt.vtu or %s/cells.vtu in ParaView.\n",
              png.c_str(), o.c_str(), o.c_str(), o.c_str());
  return kOk;
}

int run_demo(const DemoArgs& a) {
  nlohmann::json summary = {{"out", a.out}, {"steps", nlohmann::json::array()}};
  int rc;
  {
    StdoutToStderr quiet(a.json);
    rc = run_steps(a, summary);
  }
  summary["exit"] = rc;
  if (a.json) std::printf("%s\n", summary.dump(2).c_str());
  return rc;
}

}  // namespace

void add_demo_command(CLI::App& app, int& rc) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* sub = app.add_subcommand("demo", "the whole pipeline on the built-in bumpy torus");
  sub->add_option("--out", args->out, "output folder")->type_name("DIR")->capture_default_str();
  sub->add_option("--points", args->points, "points sampled inside the torus")->transform(count_in(4, 1e8))->capture_default_str();
  sub->add_option("--pieces", args->pieces, "fracture pieces")->transform(count_in(1, 100000))->capture_default_str();
  sub->add_flag("--no-oracles", args->no_oracles, "skip the CGAL and TetGen comparison");
  sub->add_flag("--json", args->json, "print a JSON summary on stdout (the steps' reports go to stderr)");
  sub->callback([args, &rc] { rc = run_demo(*args); });
}

}  // namespace dtlab::cli
