// `railjoint study`: the numerical studies of the simulation, one
// sub-command each (their own files), added here.

#include "scenes/cli/commands.h"

namespace railjoint::cli {

void add_study_command(CLI::App& app) {
  CLI::App* study = app.add_subcommand(
      "study", "Numerical studies of the simulation: error against run time, stability on stiff and extreme cases,\n"
      "inertia effects, peak forces on an elastic track, and published cases rerun");
  study->require_subcommand(1);
  add_convergence_study_command(*study);
  add_stability_study_command(*study);
  add_inertia_study_command(*study);
  add_forces_study_command(*study);
  add_published_study_command(*study);
}

}  // namespace railjoint::cli
