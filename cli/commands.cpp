#include "cli/commands.hpp"

namespace dtlab::cli {

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
  add_demo_command(app, rc);
}

}  // namespace dtlab::cli
