#pragma once
// Figures are drawn by small matplotlib scripts in scripts/plots/, run with
// Debian's /usr/bin/python3 (the python3 first on PATH may lack matplotlib;
// RAILJOINT_PYTHON names another interpreter, as the tests do). The C++ side
// writes the CSVs they read; a missing matplotlib costs the figures, never
// the numbers. A script that fails, or is interrupted, fails the run: its
// figures are not whole. Each figure is written under a temporary name and
// renamed into place (scripts/plots/atomic_save.py), so an older figure stays
// until a new one is complete. The script runs as a child that dies with
// railjoint (support/child_process.h).

#include <filesystem>
#include <string>
#include <vector>

namespace railjoint {

struct FigureResult {
  bool drawn = false;
  std::string message;  ///< what was written, or why nothing was (no python, no matplotlib)
};

/// Runs scripts/plots/<script> with the given arguments. Throws
/// std::runtime_error naming the script, its exit status and the last line of
/// its error (e.g. "IsADirectoryError: [Errno 21] Is a directory: 'po/fig6_3.png'")
/// when it fails.
FigureResult run_figure_script(const std::string& script, const std::vector<std::string>& arguments);

}  // namespace railjoint
