#pragma once
// Each sub-command of the `railjoint` CLI lives in its own file and adds
// itself to its parent here: main() adds the top-level commands, `study`
// adds its own. Handlers throw InputError for bad input; main() catches it
// once and prints one line.

#include <CLI/CLI.hpp>

namespace railjoint::cli {

void add_analytic_command(CLI::App& app);
void add_simulate_command(CLI::App& app);
void add_mesh_command(CLI::App& app);
void add_validate_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_pressure_command(CLI::App& app);
void add_sweep_command(CLI::App& app);

/// `study` and its sub-commands below.
void add_study_command(CLI::App& app);
void add_convergence_study_command(CLI::App& study);
void add_stability_study_command(CLI::App& study);
void add_inertia_study_command(CLI::App& study);
void add_forces_study_command(CLI::App& study);
void add_published_study_command(CLI::App& study);

}  // namespace railjoint::cli
