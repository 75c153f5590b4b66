#pragma once
// The data behind the thesis's figures that `railjoint validate` redraws with
// simulated points over the analytic curves (scripts/plots/validation_figures.py
// draws them): 3.7 (the step), 4.3 (y_t), 4.5 (time histories), 4.6 (impulse
// against beta), 4.7 (impulse against v), 4.8 (contact points, top view).
// Each writer opens its CSV files through `files` (the caller decides the
// folder); the simulations use `base.sim`, each on one of `jobs` threads.
// 56 simulations besides the validation scenes' own.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "scenes/scene_file.h"
#include "scenes/studies/csv_files.h"
#include "scenes/studies/validation_study.h"
#include "sim/simulate_crossing.h"

namespace railjoint {

/// Called before each figure: (index, count, what it computes).
using FigureProgress = std::function<void(std::size_t, std::size_t, const std::string&)>;

/// All of them: figure 4.5 from the validation rows of its scenes (theta =
/// 30 deg scenario 1, scenario 2 at theta = 30, 45, 60 deg), the others from
/// the thesis's defaults. Returns the names of the figure-4.5 scenes found.
std::vector<std::string> write_thesis_figure_data(const std::vector<ValidationRow>& rows, const CsvFiles& files,
                                                  int jobs = 1, const FigureProgress& progress = {});

/// Fig. 3.7: the wheel over a 0.3 m step, R = 1 m, M = 750 kg, v = 50 m/s:
/// fig3_7_analytic.csv, fig3_7_sim.csv, fig3_7_jump.csv. One simulation.
void write_figure_3_7_data(const Scene& base, const CsvFiles& files);

/// Fig. 4.3: the transition value y_t against beta for theta = 30, 45, 60 deg
/// (analytic only): fig4_3_analytic.csv.
void write_figure_4_3_data(const Scene& base, const CsvFiles& files);

/// Fig. 4.5: one validation scene's simulated and analytic time histories
/// (t = 0 at the predicted impact, x and z in the joint frame:
/// scenes/report/outputs.md): <scene>_sim.csv, <scene>_analytic.csv.
void write_figure_4_5_data(const Scene& scene, const SimulationResult& result, const CsvFiles& files);

/// Fig. 4.6: impulse against beta at y_w = 15 mm: fig4_6_analytic.csv,
/// fig4_6_sim.csv. 15 simulations.
void write_figure_4_6_data(const Scene& base, const CsvFiles& files, int jobs = 1);

/// Fig. 4.7: impulse against v, scenario 1 (y_w = 2 mm) and 2 (15 mm):
/// fig4_7_analytic.csv, fig4_7_sim.csv. 20 simulations.
void write_figure_4_7_data(const Scene& base, const CsvFiles& files, int jobs = 1);

/// Fig. 4.8: contact points A and B and the wheel centre at two-point
/// contact, top view, theta = 30, 45, 60, 90 deg, beta = 0.03:
/// fig4_8_analytic.csv (loci over y_w), fig4_8_sim.csv. 20 simulations.
void write_figure_4_8_data(const Scene& base, const CsvFiles& files, int jobs = 1);

}  // namespace railjoint
