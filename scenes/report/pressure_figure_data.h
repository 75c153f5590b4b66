#pragma once
// The CSV files behind the thesis's figures of the local model, redrawn by
// scripts/plots/pressure_figures.py (`railjoint pressure --out DIR`):
//   5.2 positions of the patch over the gap (4 steps), 5.3 relative areas,
//   5.4 absolute and relative pressure (the scene's patch and angle);
//   6.1 P/P0 and 6.2 |dP/dt| for theta = 30, 45, 60, 90 deg;
//   6.3 |dP/dt| with the five points and the patch at each (the scene's angle);
//   6.5 |dP/dt| and 6.6 P for theta = 30, 20, 10, 5 deg (the appendix's
//   create_plots_report), and the maxima for theta = 1 .. 90 deg (100 angles).
// Files: pressure_meta.csv, pressure_traversals.csv, pressure_outlines.csv,
// pressure_points.csv, pressure_theta_sweep.csv. SI units.

#include <filesystem>

#include "scenes/local_model_run.h"

namespace railjoint {

/// Junction angles of figures 6.1/6.2 and of 6.5/6.6 [deg].
inline constexpr double kFigure61Angles_deg[] = {30.0, 45.0, 60.0, 90.0};
inline constexpr double kFigure65Angles_deg[] = {30.0, 20.0, 10.0, 5.0};

/// Throws InputError naming a file that cannot be written (option "--out").
void write_pressure_figure_data(const Scene& scene, const LocalModelRun& run, const std::filesystem::path& dir);

}  // namespace railjoint
