#pragma once
// The data behind the thesis's figures that `railjoint validate` redraws with
// simulated points over the analytic curves (scripts/plots/validation_figures.py
// draws them): 3.7 (the step), 4.3 (y_t), 4.5 (time histories), 4.6 (impulse
// against beta), 4.7 (impulse against v), 4.8 (contact points, top view).
// The CSV files are opened through `files` (the caller decides the folder);
// the simulations use the thesis's default [sim], each on one of `jobs` threads.
// 56 simulations besides the validation scenes' own.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "scenes/studies/csv_files.h"
#include "scenes/studies/validation_study.h"

namespace railjoint {

/// Called before each figure: (index, count, what it computes).
using FigureProgress = std::function<void(std::size_t, std::size_t, const std::string&)>;

/// All of them: figure 4.5 from the validation rows of its scenes (theta =
/// 30 deg scenario 1, scenario 2 at theta = 30, 45, 60 deg), the others from
/// the thesis's defaults. Returns the names of the figure-4.5 scenes found.
std::vector<std::string> write_thesis_figure_data(const std::vector<ValidationRow>& rows, const CsvFiles& files,
                                                  int jobs = 1, const FigureProgress& progress = {});

}  // namespace railjoint
