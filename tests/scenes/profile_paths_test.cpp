// Measured profile files named by a scene (issue 40 items 2 and 10): a path
// in a scene file is relative to that file, one given by --set to the
// current folder; a tread that does not span the wheel's plane (y = 0) is
// refused by key and file when the scene is loaded.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/cylinder_tread.h"
#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using railjoint::testing_support::RunResult;
using railjoint::testing_support::run_railjoint;
using railjoint::testing_support::run_shell;

using railjoint::testing_support::cylinder_tread;
constexpr auto write = railjoint::testing_support::write_text_file;

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::absolute(railjoint::testing_support::scratch_path(name));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

double exact_Ns(const RunResult& r) {
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return r.exit_code == 0 ? nlohmann::json::parse(r.output).at("exact_Ns").get<double>() : 0.0;
}

// The jump of a 20 mm wide cylinder of `radius_m` 15 mm off the centre line
// (scenario 2: it depends on the radius), no profile file involved.
double cylinder_exact_Ns(double radius_m) {
  return exact_Ns(run_railjoint("analytic " + railjoint::testing_support::default_scene_path() +
                                " --set wheel.width=0.02 --set wheel.y=0.015 --set wheel.radius=" +
                                std::to_string(radius_m) + " --json"));
}

// A measured cylinder and the exact cylinder agree to rounding here; 1e-9 of
// the jump is far below the decoys' differences (0.3 m against 0.475 m).
constexpr double kSameJump = 1e-9;

// The scene's own path is its folder's wherever the command runs; a
// `--set wheel.profile=...` is the current folder's (it was read from the
// scene's folder: a file of that name there was used silently).
TEST(ProfilePaths, SceneKeysAreTheScenesAndSetKeysTheCurrentFolders) {
  const fs::path dir = fresh("profile_paths_cli");
  write(dir / "prof" / "tread.csv", cylinder_tread(0.475));
  write(dir / "prof" / "wide.csv", cylinder_tread(0.3));  // a decoy beside the scene
  write(dir / "prof" / "tread.toml", "[wheel]\nprofile = \"tread.csv\"\nwidth = 0.02\ny = 0.015\n");
  write(dir / "work" / "wide.csv", cylinder_tread(0.5));
  write(dir / "work" / "tread.csv", cylinder_tread(0.3));  // a decoy in the current folder
  const std::string cd = "cd " + (dir / "work").string() + " && " + RAILJOINT_EXE + " analytic ../prof/tread.toml --json";

  const double plain_Ns = cylinder_exact_Ns(0.475), wide_Ns = cylinder_exact_Ns(0.5);
  const double from_scene_Ns = exact_Ns(run_shell(cd));
  const double from_set_Ns = exact_Ns(run_shell(cd + " --set wheel.profile=wide.csv"));
  std::cout << "0.475 m cylinder " << plain_Ns << " N s, the scene's tread " << from_scene_Ns << " N s; 0.5 m "
            << wide_Ns << " N s, --set from the current folder " << from_set_Ns << " N s\n";
  EXPECT_NEAR(from_scene_Ns, plain_Ns, kSameJump * plain_Ns);
  EXPECT_NEAR(from_set_Ns, wide_Ns, kSameJump * wide_Ns);
}

// Item 10: a tread CSV without y = 0 gave Boost's "Requested abscissa x = 0
// ... outside of allowed range", exit 1, no key or file named.
TEST(ProfilePaths, ATreadMustSpanTheWheelsPlane) {
  const fs::path dir = fresh("profile_paths_plane");
  write(dir / "shifted.csv", cylinder_tread(0.475, 0.001));  // y from 1 mm to 41 mm
  write(dir / "s.toml", "[wheel]\nprofile = \"shifted.csv\"\nwidth = 0.02\ny = 0.015\n");
  const RunResult r = run_railjoint("analytic " + (dir / "s.toml").string());
  std::cout << r.output;
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.output.rfind("railjoint: error: " + (dir / "s.toml").string() + ": key 'wheel.profile': " +
                               (dir / "shifted.csv").string() + ": its y runs from 0.001 m to 0.041 m; a tread must "
                               "span y = 0",
                           0),
            0u)
      << r.output;
  EXPECT_EQ(r.output.find("abscissa"), std::string::npos);
}

}  // namespace
