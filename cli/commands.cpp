#include "cli/commands.hpp"

namespace dtlab::cli {

namespace {

// Every option with a value shows its default in --help (flags show none: no
// "{false}"); an option whose default is empty shows nothing.
void show_defaults(CLI::App& app) {
  for (CLI::Option* o : app.get_options())
    if (o->get_type_size_max() > 0 && o->get_default_str().empty()) {
      o->capture_default_str();
      if (o->get_default_str() == "[]") o->default_str("");  // an empty list: nothing to show
    }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) show_defaults(*sub);
}

}  // namespace

void register_commands(CLI::App& app, int& rc) {
  add_tetra_command(app, rc);
  add_check_command(app, rc);
  add_oracle_command(app, rc);
  add_fuzz_command(app, rc);
  add_experiment_command(app, rc);
  add_mesh_command(app, rc);
  add_sample_command(app, rc);
  add_voronoi_command(app, rc);
  add_fracture_command(app, rc);
  add_bench_command(app, rc);
  add_predicates_command(app, rc);
  add_demo_command(app, rc);
  show_defaults(app);
}

}  // namespace dtlab::cli
