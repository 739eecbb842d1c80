#pragma once
#include "cli/command.hpp"

namespace dtlab::cli {

void add_tetra_command(CLI::App& app, int& rc);
void add_fuzz_command(CLI::App& app, int& rc);
void add_check_command(CLI::App& app, int& rc);
void add_oracle_command(CLI::App& app, int& rc);
void add_sample_command(CLI::App& app, int& rc);
void add_voronoi_command(CLI::App& app, int& rc);
void add_fracture_command(CLI::App& app, int& rc);
void add_mesh_command(CLI::App& app, int& rc);
void add_demo_command(CLI::App& app, int& rc);
void add_experiment_command(CLI::App& app, int& rc);
void add_bench_command(CLI::App& app, int& rc);
void add_predicates_command(CLI::App& app, int& rc);

// Registers every subcommand; defined in commands.cpp.
void register_commands(CLI::App& app, int& rc);

}  // namespace dtlab::cli
