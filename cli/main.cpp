// dtlab: a verification-focused testbed for robust 3D Delaunay tetrahedralization.
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/cli_error.hpp"
#include "cli/command.hpp"
#include "cli/commands.hpp"
#include "dtlab/build_info.hpp"
#include "kernel/exit_guard.hpp"

namespace {

// `dtlab --version`: what a paper needs to name the exact build.
std::string version_text() {
  using namespace dtlab;
  return std::string("dtlab ") + build_version() + "\ncommit " + build_commit() + "\ncompiler " +
         build_compiler() + " (" + build_type() + ")\nCGAL " + build_cgal_version() + "\nGMP " +
         build_gmp_version() + " (runtime " + runtime_gmp_version() + ")\nTetGen " + build_tetgen_version();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace dtlab::cli;
  // A SIGCHLD ignored by whoever started us (inherited across exec) would reap every
  // child before its wait could read its end: every peer "wait failed".
  std::signal(SIGCHLD, SIG_DFL);
  // Ctrl-C, SIGTERM, SIGHUP: peers killed, temp files removed, then the signal's status.
  dtlab::install_interrupt_cleanup();
  CLI::App app{"dtlab: robust 3D Delaunay tetrahedralization testbed", "dtlab"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text, "print the version, git commit and library versions");
  int rc = kOk;
  register_commands(app, rc);
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (...) {
    // Every error, of usage or of an input file, in one style (cli/cli_error.hpp).
    return report_error(current_error(command_path(app, args)), wants_json(args));
  }
  return rc;
}
