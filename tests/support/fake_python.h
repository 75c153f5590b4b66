#pragma once
// A stand-in for the figure scripts' interpreter (RAILJOINT_PYTHON, see
// scenes/cli/figure_script.h): a shell script that answers the matplotlib
// check ("-c import matplotlib") with success and does `body` for the figure
// script itself, so a test can make a script fail or take its time without
// depending on matplotlib.

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/scratch_dir.h"

namespace railjoint::testing_support {

/// "RAILJOINT_PYTHON=<script> ", to put before a command line.
inline std::string with_fake_python(const std::string& body) {
  const std::filesystem::path script = scratch_path("fake_python");
  std::ofstream(script) << "#!/bin/sh\nif [ \"$1\" = -c ]; then exit 0; fi\n" << body << "\n";
  std::filesystem::permissions(script, std::filesystem::perms::owner_all);
  return "RAILJOINT_PYTHON=" + script.string() + " ";
}

}  // namespace railjoint::testing_support
