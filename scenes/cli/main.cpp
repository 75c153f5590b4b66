// railjoint: checks the kinematic model of a wheel crossing an inclined dipped
// insulated rail joint against a rigid-body simulation.

#include <cstdio>
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "models/input_error.h"
#include "scenes/cli/commands.h"

int main(int argc, char** argv) {
  CLI::App app{
      "railjoint: vertical impact of a train wheel crossing an inclined (non-orthogonal) dipped\n"
      "insulated rail joint. Analytic kinematic model (thesis ch. 3-4) checked against a Bullet\n"
      "rigid-body simulation; the local contact-pressure model of a patch crossing the end-post\n"
      "gap (ch. 5-6). Units are SI (m, kg, s, rad) unless a key or flag says _deg.",
      "railjoint"};
  app.require_subcommand(1);
  railjoint::cli::add_analytic_command(app);
  railjoint::cli::add_simulate_command(app);
  railjoint::cli::add_mesh_command(app);
  railjoint::cli::add_validate_command(app);
  railjoint::cli::add_study_command(app);
  railjoint::cli::add_render_command(app);
  railjoint::cli::add_pressure_command(app);
  railjoint::cli::add_sweep_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  } catch (const railjoint::InputError& error) {
    std::cerr << "railjoint: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "railjoint: error: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
