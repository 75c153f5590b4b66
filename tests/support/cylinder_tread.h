#pragma once
// A measured tread file for the tests of profile files: a cylinder written
// as (y, r) points, which the model must take for the plain cylinder of the
// same radius (wheel.radius, no file): an expected value from another route.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace railjoint::testing_support {

/// A cylinder of `radius_m` as a tread CSV: (y, r) every 5 mm over [y0, y0 + 40 mm].
inline std::string cylinder_tread(double radius_m, double y0_m = -0.02) {
  std::ostringstream text;
  text << "y_m,r_m\n";
  for (int i = 0; i <= 8; ++i) text << y0_m + i * 0.005 << "," << radius_m << "\n";
  return text.str();
}

/// Writes `text` as `path`, making its folders.
inline void write_text_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

}  // namespace railjoint::testing_support
