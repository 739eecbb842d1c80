// dtlab: a verification-focused testbed for robust 3D Delaunay tetrahedralization.
#include <cstdio>
#include <exception>

#include "cli/command.hpp"
#include "cli/commands.hpp"
#include "kernel/input_error.hpp"

int main(int argc, char** argv) {
  using namespace dtlab::cli;
  CLI::App app{"dtlab: robust 3D Delaunay tetrahedralization testbed", "dtlab"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "dtlab 0.1.0");
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
