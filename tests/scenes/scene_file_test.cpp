// Scene files: defaults, overrides and the errors a user sees.

#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "scenes/scene_file.h"
#include "sim/crossing_model.h"
#include "support/input_error.h"

namespace railjoint {
namespace {

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_scene(text, "test.toml", overrides);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

// The keys the reader used, for the reports' "scene" block: what the file
// gave, every default, and joint.length derived when the file gives none.
const ResolvedKey* resolved(const Scene& scene, const std::string& section, const std::string& key) {
  for (const ResolvedSection& s : scene.resolved) {
    if (s.name != section) continue;
    for (const ResolvedKey& k : s.keys) {
      if (k.key == key) return &k;
    }
  }
  return nullptr;
}

TEST(SceneFile, RecordsEveryKeyReadWithTheValueUsed) {
  const Scene scene = parse_scene("[joint]\ntheta_deg = 45\n[wheel]\nspeed = 30.0\n", "keys.toml", {"wheel.y=0.01"});
  const ResolvedKey* theta = resolved(scene, "joint", "theta_deg");
  ASSERT_NE(theta, nullptr);
  EXPECT_EQ(std::get<double>(theta->value), 45.0);  // in the file's unit, degrees
  EXPECT_EQ(theta->source, KeySource::given);
  EXPECT_EQ(std::get<double>(resolved(scene, "wheel", "y")->value), 0.01);
  const ResolvedKey* radius = resolved(scene, "wheel", "radius");
  ASSERT_NE(radius, nullptr);
  EXPECT_EQ(std::get<double>(radius->value), 0.475);
  EXPECT_EQ(radius->source, KeySource::default_value);
  EXPECT_EQ(std::get<std::string>(resolved(scene, "joint", "kind")->value), "inclined");
  EXPECT_EQ(std::get<std::string>(resolved(scene, "sim", "mode")->value), "kinematic");
  EXPECT_EQ(std::get<long long>(resolved(scene, "sim", "solver_iterations")->value), scene.sim.solver_iterations);
  EXPECT_NE(resolved(scene, "contact_patch", "shape"), nullptr);
  const ResolvedKey* length = resolved(scene, "joint", "length");
  ASSERT_NE(length, nullptr);
  EXPECT_EQ(length->source, KeySource::derived);
  EXPECT_EQ(std::get<double>(length->value), scene.joint.length_m);
  const Scene given = parse_scene("[joint]\nlength = 3.0\n", "length.toml");
  EXPECT_EQ(resolved(given, "joint", "length")->source, KeySource::given);
}

TEST(SceneFile, EmptySceneTakesTheThesisDefaults) {
  const Scene scene = parse_scene("", "empty.toml");
  EXPECT_NEAR(scene.joint.theta_rad, std::numbers::pi / 6, 1e-15);
  EXPECT_EQ(scene.joint.beta_rad, 0.03);
  EXPECT_EQ(scene.wheel.radius_m, 0.475);
  EXPECT_EQ(scene.wheel.lateral_m, 0.015);
  EXPECT_EQ(scene.name, "empty");
}

TEST(SceneFile, KeysAreReadInSIUnitsAndDegrees) {
  const Scene scene = parse_scene(
      "[joint]\nkind = \"step\"\nstep_height = 0.002\n[wheel]\nradius = 0.45\nspeed = 10\ny = 0\n", "s.toml");
  EXPECT_EQ(scene.joint.kind, JointKind::step);
  EXPECT_EQ(scene.joint.step_height_m, 0.002);
  EXPECT_NEAR(parse_scene("[joint]\ntheta_deg = 45\n", "t.toml").joint.theta_rad, std::numbers::pi / 4, 1e-15);
  EXPECT_EQ(scene.wheel.radius_m, 0.45);
  EXPECT_EQ(scene.wheel.speed_m_per_s, 10.0);  // an integer is accepted for a number
}

TEST(SceneFile, OverridesReplaceFileValues) {
  const Scene scene = parse_scene("[wheel]\nspeed = 50.0\n", "o.toml", {"wheel.speed=30", "joint.kind=step"});
  EXPECT_EQ(scene.wheel.speed_m_per_s, 30.0);
  EXPECT_EQ(scene.joint.kind, JointKind::step);
}

TEST(SceneFile, OverridesTakeDecimalsAsAShellUserWritesThem) {
  // TOML refuses .005, 5. and 050; on the command line they mean 0.005, 5, 50.
  const Scene scene = parse_scene("", "test.toml",
                                  {"wheel.y=.005", "wheel.speed=+5.", "joint.theta_deg=050", "sim.solver_iterations=020"});
  EXPECT_EQ(scene.wheel.lateral_m, 0.005);
  EXPECT_EQ(scene.wheel.speed_m_per_s, 5.0);
  EXPECT_NEAR(scene.joint.theta_rad, 50.0 * std::numbers::pi / 180.0, 1e-15);
  EXPECT_EQ(scene.sim.solver_iterations, 20);  // an integer key takes 020 as an integer
  EXPECT_EQ(parse_scene("", "test.toml", {"wheel.y=+.005"}).wheel.lateral_m, 0.005);
  // Not a number end to end, or not finite: still an error naming the key.
  EXPECT_NE(error_of("", {"wheel.y=.005m"}).find("key 'wheel.y': must be a number in [-1, 1] m, got \".005m\""),
            std::string::npos);
  EXPECT_NE(error_of("", {"wheel.speed=1e400"}).find("is not a valid number"), std::string::npos);
}

// Issue 40, item 17: `--set wheel.speed=120km/h` printed toml++'s "Error while
// parsing decimal integer: expected digit, saw 'k'". A number with a unit
// after it is refused by the key, in the unit the key takes.
TEST(SceneFile, ANumberWithAUnitIsRefusedInTheKeysUnit) {
  EXPECT_EQ(error_of("", {"wheel.speed=120km/h"}),
            "test.toml: key 'wheel.speed': must be a number in [0.1, 1000] m/s, got \"120km/h\": write the number "
            "alone, in m/s");
  EXPECT_NE(error_of("", {"joint.theta_deg=37deg"}).find("got \"37deg\": write the number alone, in deg"),
            std::string::npos);
  // The same in a scene file.
  EXPECT_NE(error_of("[wheel]\nspeed = \"120km/h\"\n").find("write the number alone, in m/s"), std::string::npos);
  // A file name that starts with a digit is a file name (joint.rail_profile's reader judges it).
  EXPECT_EQ(error_of("", {"joint.rail_profile=2mm.csv"}).find("not a valid number"), std::string::npos);
  // So is a path that starts like a number: `--set joint.rail_profile=../head.csv`
  // was "not a valid number: expected decimal digit, saw '.'", and the file
  // was never looked for.
  for (const std::string path : {"../head.csv", "./head.csv", ".\\head.csv", "1/head.csv"}) {
    const std::string error = error_of("", {"joint.rail_profile=" + path});
    EXPECT_EQ(error.find("not a valid number"), std::string::npos) << error;
    EXPECT_NE(error.find("joint.rail_profile"), std::string::npos) << error;
  }
}

// Issue 40, item 7: `--set $'wheel.speed=30\njoint.beta=0.9'` ran at speed 30
// with beta 0.03 (the line after the break dropped), exit 0. A --set holding
// a control character is refused, naming it.
TEST(SceneFile, AnOverrideWithALineBreakIsRefused) {
  const std::vector<std::string> overrides = {"wheel.speed=30\njoint.beta=0.9", "wheel.speed=30\rjoint.beta=0.9",
                                              std::string("name=a\0b", 9), "name=a\x1b[2Jb", "wheel.speed=30\x7f"};
  for (const std::string& bad : overrides) {
    const std::string error = error_of("", {bad});
    std::cout << error << '\n';
    EXPECT_NE(error.find("--set takes one section.key=value without line breaks or other control characters"),
              std::string::npos)
        << error;
  }
  EXPECT_EQ(parse_scene("", "test.toml", {"wheel.speed\t=\t30"}).wheel.speed_m_per_s, 30.0);  // a tab is layout
}

TEST(SceneFile, ANameThatIsNoTextIsAnError) {
  EXPECT_EQ(error_of("name = 5\n"), "test.toml: key 'name': must be a text in quotes, e.g. name = \"my joint\"");
  EXPECT_EQ(parse_scene("name = \"mine\"\n", "test.toml").name, "mine");
}

TEST(SceneFile, ErrorsNameFileKeyAndRange) {
  // An unknown key names the keys its section asked for, closest first (issue 29, item 6).
  // The quantity without its unit suffix is that key (issue 40, item 17: "theta" is 2 edits from "beta", 4
  // from "theta_deg", and the list read "beta, depth, theta_deg").
  EXPECT_EQ(error_of("[joint]\ntheta = 30\n").rfind("test.toml: key 'joint.theta': unknown key in [joint] (did you mean "
                                                     "'theta_deg'?); [joint] takes theta_deg, beta, depth, ", 0),
            0u)
      << error_of("[joint]\ntheta = 30\n");
  EXPECT_EQ(error_of("[wheel]\nsped = 30\n"),
            // edit distances from "sped": speed 1, mass 4, y 4 (ties by name), width 5, radius 6
            "test.toml: key 'wheel.sped': unknown key in [wheel] (did you mean 'speed'?); [wheel] takes speed, mass, "
            "y, width, radius, profile, conicity (closest first)");
  EXPECT_EQ(error_of("[joint]\ntheta_deg = 120\n"), "test.toml: key 'joint.theta_deg': must be in (0, 90] deg, got 120");
  EXPECT_EQ(error_of("[joint]\ntheta_deg = 0\n"), "test.toml: key 'joint.theta_deg': must be in (0, 90] deg, got 0");
  EXPECT_EQ(error_of("[joint]\nbeta = -0.01\n"), "test.toml: key 'joint.beta': must be in [0, 1] rad, got -0.01");
  EXPECT_EQ(error_of("[wheel]\nspeed = \"fast\"\n"),
            "test.toml: key 'wheel.speed': must be a number in [0.1, 1000] m/s, got a string");
  EXPECT_EQ(error_of("[wheel]\nmass = 0\n"), "test.toml: key 'wheel.mass': must be in [1, 10000000] kg, got 0");
  EXPECT_EQ(error_of("[wheel]\nradius = -1\n"), "test.toml: key 'wheel.radius': must be in [0.05, 10] m, got -1");
  EXPECT_NE(error_of("[wheel]\ny = 0.025\n").find("test.toml: key 'wheel.y': lateral position must lie on the rail head"),
            std::string::npos);
  EXPECT_NE(error_of("[joint]\nkind = \"step\"\nstep_height = 0.5\n").find("key 'joint.step_height'"),
            std::string::npos);
  EXPECT_EQ(error_of("[joint]\nkind = \"square\"\n"),
            "test.toml: key 'joint.kind': must be one of \"inclined\", \"step\", got \"square\"");
  EXPECT_EQ(error_of("[wheels]\nradius = 1\n"), "test.toml: key 'wheels': unknown section");
  EXPECT_NE(error_of("[joint\n").find("test.toml: not valid TOML (line 1"), std::string::npos);
  EXPECT_NE(error_of("", {"wheel.speed"}).find("--set expects section.key=value"), std::string::npos);
  EXPECT_EQ(error_of("", {"wheel.speed=-3"}), "test.toml: key 'wheel.speed': must be in [0.1, 1000] m/s, got -3");
  EXPECT_EQ(error_of("[joint]\nhalf_width = inf\n"),
            "test.toml: key 'joint.half_width': must be a finite number in (0, 1] m, got inf");
  EXPECT_EQ(error_of("", {"sim.preload=inf"}), "test.toml: key 'sim.preload': must be a finite number in [0, 1000000000] N, got inf");
}

// Issue 29, item 5: a key the joint's kind does not use changed nothing and
// passed (`--set joint.kind=step --set joint.theta_deg=45` ran a square step).
TEST(SceneFile, AKeyTheJointKindDoesNotUseIsRefused) {
  EXPECT_EQ(error_of("", {"joint.kind=step", "joint.theta_deg=45"}).rfind(
                "test.toml: key 'joint.theta_deg': applies to kind = \"inclined\"", 0),
            0u);
  EXPECT_EQ(error_of("", {"joint.kind=step", "joint.beta=0.05"}).rfind(
                "test.toml: key 'joint.beta': applies to kind = \"inclined\"", 0),
            0u);
  EXPECT_EQ(error_of("", {"joint.step_height=0.001"}).rfind(
                "test.toml: key 'joint.step_height': applies to kind = \"step\"", 0),
            0u);
}

// Issue 29, item 6: no way to drop a key from the command line; --unset
// takes the file's key away, so it takes its default.
TEST(SceneFile, UnsetDropsAKeyTheFileGives) {
  const std::string text = "[wheel]\nspeed = 10.0\ny = 0.002\n";
  EXPECT_DOUBLE_EQ(parse_scene(text, "u.toml").wheel.speed_m_per_s, 10.0);
  const Scene unset = parse_scene(text, "u.toml", {}, SceneCheck::model, {"wheel.speed"});
  EXPECT_DOUBLE_EQ(unset.wheel.speed_m_per_s, WheelParams{}.speed_m_per_s);
  EXPECT_FALSE(unset.given("wheel.speed"));
  EXPECT_DOUBLE_EQ(unset.wheel.lateral_m, 0.002);
  // Unset then set: the --set wins, as the command line is read after the file.
  EXPECT_DOUBLE_EQ(parse_scene(text, "u.toml", {"wheel.speed=20"}, SceneCheck::model, {"wheel.speed"}).wheel.speed_m_per_s,
                   20.0);
  try {
    parse_scene(text, "u.toml", {}, SceneCheck::model, {"wheel.mass"});
    ADD_FAILURE() << "unset of a key the file does not give";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "u.toml: key 'wheel.mass': --unset: the scene file does not give this key, so there is nothing to unset");
  }
}

// Issue 29, item 6: a value that a unit slip explains says so; spaces around
// a --set assignment are layout, as in a scene file.
TEST(SceneFile, AValueOutOfRangeByAUnitSlipSaysSo) {
  EXPECT_EQ(error_of("", {"wheel.y=15"}),
            "test.toml: key 'wheel.y': must be in [-1, 1] m, got 15 (if that is 15 mm: the key is in metres, 0.015)");
  EXPECT_EQ(error_of("", {"joint.beta=3"}),
            "test.toml: key 'joint.beta': must be in [0, 1] rad, got 3 (if that is 3 deg: the key is in radians, "
            "0.05235987756)");
  // 1.5 m = 1500 mm is out of range in millimetres too: no hint.
  EXPECT_EQ(error_of("", {"wheel.y=1500"}), "test.toml: key 'wheel.y': must be in [-1, 1] m, got 1500");
  EXPECT_DOUBLE_EQ(parse_scene("", "test.toml", {" wheel.speed = 30 "}).wheel.speed_m_per_s, 30.0);
  EXPECT_EQ(parse_scene("", "test.toml", {"joint.kind =  step"}).joint.kind, JointKind::step);
}

// Issue 15 row 8: render.reference_z = 1e300 and render.view_width = 1e-300
// were taken, wheel.mass = 5e-324 passed every check (and simulated to "no
// impact"), and keys without bounds printed "[-inf, inf]".
TEST(SceneFile, EveryKeyHasAPlausibleFiniteRange) {
  EXPECT_EQ(error_of("[render]\nreference_z = 1e300\n"),
            "test.toml: key 'render.reference_z': must be in [-20, 20] m, got 1e+300");
  EXPECT_EQ(error_of("[render]\nview_width = 1e-300\n"),
            "test.toml: key 'render.view_width': must be in [0.0001, 100] m, got 1e-300");
  EXPECT_EQ(error_of("[wheel]\nmass = 5e-324\n"), "test.toml: key 'wheel.mass': must be in [1, 10000000] kg, got 4.940656458e-324");
  EXPECT_EQ(error_of("[wheel]\nmass = 1\n"), "no error");
  // Every key given a text: the message shows its range, and no range is
  // unbounded. (Inertial keys need the mode and what they apply with.)
  const char* const inertial = "mode = \"inertial\"\nhorizontal = \"free\"\nfriction = 0.2\n";
  const std::string hertz = "[sim]\nmode = \"inertial\"\n[contact]\nlaw = \"hertz\"\n";
  const std::vector<std::pair<std::string, std::vector<std::string>>> sections = {
      {"[joint]\n", {"theta_deg", "beta", "half_width", "length", "depth", "gap", "step_height"}},
      {"[wheel]\n", {"radius", "mass", "width", "y", "speed"}},
      {"[sim]\n", {"time_step", "refined_time_step", "refine_distance", "refine_hold", "margin",
                    "contact_breaking_threshold", "contact_processing_threshold", "split_impulse_threshold", "slop",
                    "solver_iterations", "preload", "friction", "restitution", "disc_half_width", "approach_distance",
                    "run_out_time"}},
      {std::string("[sim]\n") + inertial,
       {"wheel_load", "carrier_mass", "radius_of_gyration", "flat_approach"}},
      {"[sim]\nmode = \"inertial\"\n[contact]\nlaw = \"linear\"\n", {"stiffness", "damping"}},
      {hertz, {"hertz_constant", "restitution"}},
      {"[contact]\nlaw = \"hertz\"\n[sim]\nmode = \"inertial\"\n", {"force_time_step"}},
      {hertz + "[track]\nmodel = \"lumped\"\n",
       {"rail_mass", "pad_stiffness", "pad_damping", "sleeper_mass", "ballast_stiffness", "ballast_damping"}},
      {hertz + "[vehicle]\nmodel = \"sprung\"\n", {"sprung_mass", "primary_stiffness", "primary_damping"}},
      {hertz + "[track]\nmodel = \"discrete\"\n",
       {"bending_stiffness", "mass_per_length", "sleeper_spacing", "joint_bending_stiffness"}},
      {"[render]\n", {"width", "height", "fps", "t_start", "t_end", "exaggeration", "reference_z", "view_width",
                       "video_fps"}},
      {"[contact_patch]\n", {"length", "width", "normal_force", "steps"}},
      {"[contact_patch]\nshape = \"polygon\"\n", {"vertices"}},
      {"[contact_patch]\nsize = \"hertz\"\n", {"crown_radius"}},
      {"[contact]\n", {"youngs_modulus", "poisson_ratio"}},
  };
  int keys = 0;
  for (const auto& [section, names] : sections) {
    for (const std::string& name : names) {
      const std::string error = error_of(section + name + " = \"text\"\n");
      std::cout << error << "\n";
      EXPECT_NE(error.find("must be"), std::string::npos) << error;
      EXPECT_NE(error.find(", got a string"), std::string::npos) << error;
      EXPECT_EQ(error.find("inf"), std::string::npos) << error;
      ++keys;
    }
  }
  EXPECT_EQ(keys, 67);
}

// Issue 15 row 11: the thesis's section-3.2.2 example (a 0.3 m step under a
// 1 m wheel) was refused for the default 1 m rail, though the analytic model
// has no rail of its own: without joint.length the rails are as long as the
// model needs; a length the user gives is still checked.
TEST(SceneFile, WithoutARailLengthTheRailsAreAsLongAsTheModelNeeds) {
  const std::vector<std::string> thesis = {"joint.kind=step", "joint.step_height=0.3", "wheel.radius=1", "wheel.y=0"};
  // The geometry alone (what `mesh` checks): the contact leads the centre by
  // sqrt(2 R u0 - u0^2) = sqrt(0.51) = 0.714 m on a step (x_A), bounded in
  // the check by sqrt(2 R u0) = 0.775 m each side: L >= 1.549 m.
  const Scene geometry = parse_scene("", "test.toml", thesis, SceneCheck::geometry);
  EXPECT_FALSE(geometry.given("joint.length"));
  EXPECT_TRUE(geometry.given("joint.step_height"));
  EXPECT_TRUE(geometry.given("wheel.y"));
  EXPECT_NEAR(geometry.joint.length_m, 2.0 * std::sqrt(0.6), 1e-9);

  // With the model (what `analytic` and `simulate` read): at least that,
  // and rails the simulation can be built on (its approach and run-out).
  const Scene scene = parse_scene("", "test.toml", thesis);
  std::cout << "derived rail length " << scene.joint.length_m << " m\n";
  EXPECT_GE(scene.joint.length_m, 2.0 * std::sqrt(0.6) - 1e-12);
  ASSERT_TRUE(scene.prediction.has_value());
  EXPECT_NEAR(scene.prediction->x_A_m, std::sqrt(0.51), 1e-9);
  EXPECT_NO_THROW(build_crossing_model(scene.joint, scene.wheel, scene.sim));

  // The inertial default scene flies ~0.85 m past the joint at 50 m/s: the
  // default 1 m of rail cannot carry its landing, the derived length can.
  const Scene inertial = parse_scene("", "test.toml", {"sim.mode=inertial"});
  EXPECT_GT(inertial.joint.length_m, 2.0);
  EXPECT_NO_THROW(build_crossing_model(inertial.joint, inertial.wheel, inertial.sim));

  // A length the scene gives is never changed: too short is refused.
  std::vector<std::string> with_length = thesis;
  with_length.push_back("joint.length=1");
  EXPECT_NE(error_of("", with_length).find("key 'joint.length': rail length L must be >= 1.54919 m"), std::string::npos);
  EXPECT_THROW(build_crossing_model(parse_scene("", "test.toml", {"sim.mode=inertial", "joint.length=1"}).joint,
                                    inertial.wheel, inertial.sim),
               InputError);
  // A scene that fits on the default 1 m keeps it.
  EXPECT_EQ(parse_scene("", "test.toml").joint.length_m, 1.0);
}

// Issue 15 row 1 (the reader's side): text that could nest deeper than the
// TOML parser can follow is refused before it is parsed; strings and
// comments full of dots are not counted.
TEST(SceneFile, TextTooLargeOrTooDeepIsRefusedBeforeParsing) {
  std::string deep = "a";
  for (int i = 0; i < 1001; ++i) deep += ".a";  // 1001 dots
  EXPECT_NE(error_of(deep + " = 1\n").find("test.toml: line 1 holds more than 1000 dots, brackets and braces"),
            std::string::npos);
  EXPECT_NE(error_of("[wheel]\ny = 0.01\n" + deep + " = 1\n").find("line 3"), std::string::npos);
  EXPECT_NE(error_of("", {"wheel.y=[" + std::string(2000, '[')}).find("test.toml: key 'wheel.y': line 1 holds more"),
            std::string::npos);
  // An array inside an inline table may span lines (TOML 1.0), and each of
  // its lines may open a key ~1000 levels deep: 110 lines of 997 dots (220
  // kB) overflowed the stack inside toml++. The brackets left open count on
  // the next line: line 1 holds 1000 marks and leaves 3 open, line 2 then
  // reaches 3 + 999.
  std::string key_997 = "a";
  for (int i = 0; i < 997; ++i) key_997 += ".a";
  std::string spanning = "x = [{" + key_997 + " = [\n";
  for (int i = 1; i < 110; ++i) spanning += "{" + key_997 + " = [\n";
  spanning += "1";
  for (int i = 0; i < 110; ++i) spanning += "]}";
  spanning += "]\n";
  EXPECT_NE(error_of(spanning).find("test.toml: line 2 holds more than 1000 dots, brackets and braces"),
            std::string::npos);
  // Arrays and inline tables that close on their own lines carry nothing over.
  // (2000 lines of 6 marks each, then an array over four lines; the scene's
  // own error is an unknown key, not the nesting.)
  std::string many_short_lines;
  for (int i = 0; i < 2000; ++i) {
    many_short_lines += "k";  // (+= each: GCC 12 warns falsely, -Wrestrict, on "k" + string)
    many_short_lines += std::to_string(i);
    many_short_lines += " = [{a.b = 1.5}, [2.5]]\n";
  }
  many_short_lines += "t = [\n  1.0e-4,\n  2.0e-4,\n]\n";
  EXPECT_EQ(error_of(many_short_lines).find("holds more"), std::string::npos) << error_of(many_short_lines);
  const std::string dots(5000, '.');
  EXPECT_EQ(error_of("description = \"" + dots + "\"\n# " + dots + "\nname = '" + dots + "'\n"), "no error");
  EXPECT_EQ(error_of("description = \"\"\"\n" + dots + "\n\\\"\"\"" + dots + "\"\"\"\n"), "no error");
  const std::string large(2 << 20, '#');
  EXPECT_NE(error_of(large).find("test.toml: is 2097152 bytes of TOML"), std::string::npos);
}

// Found by tests/fuzz (scene_reader and set_override, regressions/): where
// toml++ 3.3 asks whether a non-ASCII character is whitespace it can reach
// TOML_UNREACHABLE, undefined behaviour (upstream issue 190). TOML allows
// non-ASCII text only in strings and comments: elsewhere it is refused first.
TEST(SceneFile, NonAsciiOutsideStringsAndCommentsIsRefusedBeforeParsing) {
  EXPECT_EQ(error_of("\xef\xb3\xbf = 1\n"),  // U+FCFF, the fuzzer's
            "test.toml: line 1: a non-ASCII character outside a string or comment (TOML allows them only inside "
            "strings and comments)");
  EXPECT_NE(error_of("[joint]\ntheta_deg = 30 \xc2\xa7\n").find("line 2: a non-ASCII character outside"), std::string::npos);
  // Upstream issue 190's own example: U+00A7 after a line-ending backslash.
  EXPECT_NE(error_of("description = \"\"\"\\\n\xc2\xa7\"\"\"\n").find("line 2: a non-ASCII character after a backslash in "
                                                                     "a multi-line string"),
            std::string::npos);
  // The fuzzer's: right after a backslash in a multi-line string.
  EXPECT_NE(error_of("\"\"\"\\\xee\xbb\xaf").find("line 1: a non-ASCII character after a backslash"), std::string::npos);
  // A quote where no string can start (after '+') opens none: non-ASCII after it is refused.
  EXPECT_NE(error_of("name = +\"g\xc3\xa9\"\n").find("line 1: a non-ASCII character outside"), std::string::npos);
  // In strings and comments they are text, as TOML says.
  EXPECT_EQ(error_of("name = \"Zürich \xc2\xa7\"  # Gleisstoß\ndescription = \"\"\"\n§ \\\n  x\"\"\"\n"), "no error");
  // A bare --set word is text, non-ASCII or not; after a quoted one it is refused.
  EXPECT_EQ(parse_scene("", "test.toml", {"joint.kind=step", "wheel.y=0", "joint.step_height=0.001"}).name, "test");
  EXPECT_NE(error_of("", {"joint.kind=stép"}).find("key 'joint.kind': must be one of \"inclined\", \"step\", got \"stép\""),
            std::string::npos);
  EXPECT_NE(error_of("", {"joint.kind=\"step\"\xef\xb3\xbf"}).find("key 'joint.kind': line 1: a non-ASCII character"),
            std::string::npos);
}

TEST(SceneFile, UnreadableFileIsNamed) {
  try {
    load_scene("/nonexistent/scene.toml");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), "/nonexistent/scene.toml: no such scene file");
  }
}

}  // namespace
}  // namespace railjoint
