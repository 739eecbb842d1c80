// dtlab: a verification-focused testbed for robust 3D Delaunay tetrahedralization.
#include <cstdio>
#include <exception>
#include <string>

#include "cli/command.hpp"
#include "cli/commands.hpp"
#include "dtlab/build_info.hpp"
#include "kernel/input_error.hpp"

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
  CLI::App app{"dtlab: robust 3D Delaunay tetrahedralization testbed", "dtlab"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text, "print the version, git commit and library versions");
  int rc = kOk;
  register_commands(app, rc);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kOk : kBadInput;
  } catch (const dtlab::InputError& e) {
    std::fprintf(stderr, "dtlab: %s\n", e.what());
    return kBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dtlab: error: %s\n", e.what());
    return kBadInput;
  }
  return rc;
}
