#pragma once
// Each sub-command of the `railjoint` CLI lives in its own file and adds
// itself to the app here. Handlers throw InputError for bad input; main()
// catches it once and prints one line.

#include <CLI/CLI.hpp>

namespace railjoint::cli {

void add_analytic_command(CLI::App& app);
void add_simulate_command(CLI::App& app);
void add_mesh_command(CLI::App& app);
void add_validate_command(CLI::App& app);
void add_study_command(CLI::App& app);
void add_inertia_study_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_pressure_command(CLI::App& app);

}  // namespace railjoint::cli
