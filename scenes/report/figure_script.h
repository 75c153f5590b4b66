#pragma once
// Figures are drawn by small matplotlib scripts in scripts/plots/, run with
// Debian's /usr/bin/python3 (the python3 first on PATH may lack matplotlib).
// The C++ side writes the CSVs they read; a missing matplotlib costs the
// figures, never the numbers.

#include <filesystem>
#include <string>
#include <vector>

namespace railjoint {

struct FigureResult {
  bool drawn = false;
  std::string message;  ///< what was written, or why nothing was
};

/// Runs scripts/plots/<script> with the given arguments.
FigureResult run_figure_script(const std::string& script, const std::vector<std::string>& arguments);

}  // namespace railjoint
