// The [contact_patch] section (scenes/contact_patch_section.cpp): absent, it
// takes table 6.1's values; present, its keys reach the local model; theta
// and the gap come from [joint], the speed and wheel radius from [wheel].

#include <cmath>
#include <cstdio>
#include <string>
#include <numbers>

#include <gtest/gtest.h>

#include "scenes/contact_patch_section.h"
#include "scenes/scene_file.h"
#include "support/input_error.h"

namespace railjoint {
namespace {

TEST(ContactPatchSection, AbsentSectionTakesTableSixOne) {
  const Scene scene = parse_scene("[joint]\ngap = 0.006\n", "t.toml", {}, SceneCheck::keys_only);
  const ContactPatchSettings& s = scene.contact_patch;
  EXPECT_EQ(s.patch.shape, PatchShape::ellipse);
  EXPECT_EQ(s.size, PatchSize::given);
  EXPECT_DOUBLE_EQ(s.patch.length_m, 0.016);
  EXPECT_DOUBLE_EQ(s.patch.width_m, 0.012);
  EXPECT_DOUBLE_EQ(s.normal_force_N, 112.5e3);
  EXPECT_EQ(s.steps, 1000);
  const PressureInputs in = local_model_inputs_of(scene);
  EXPECT_DOUBLE_EQ(in.gap.gap_m, 0.006);
  EXPECT_DOUBLE_EQ(in.gap.theta_rad, std::numbers::pi / 6.0);  // the default joint's 30 deg
  EXPECT_DOUBLE_EQ(in.speed_m_per_s, 50.0);
}

TEST(ContactPatchSection, KeysReachTheModel) {
  const Scene scene = parse_scene(
      "[joint]\ntheta_deg = 45.0\ngap = 0.004\n[wheel]\nspeed = 20.0\n"
      "[contact_patch]\nshape = \"polygon\"\nvertices = 64\nlength = 0.014\nwidth = 0.010\nnormal_force = 1e5\nsteps = 50\n",
      "t.toml", {}, SceneCheck::keys_only);
  const PressureInputs in = local_model_inputs_of(scene);
  EXPECT_EQ(in.patch.shape, PatchShape::polygon);
  EXPECT_EQ(in.patch.vertices, 64);
  EXPECT_DOUBLE_EQ(in.patch.length_m, 0.014);
  EXPECT_DOUBLE_EQ(in.patch.width_m, 0.010);
  EXPECT_DOUBLE_EQ(in.normal_force_N, 1e5);
  EXPECT_EQ(in.steps, 50);
  EXPECT_DOUBLE_EQ(in.gap.theta_rad, std::numbers::pi / 4.0);
  EXPECT_DOUBLE_EQ(in.speed_m_per_s, 20.0);
}

// size = "hertz": the wheel radius from [wheel]; a bigger wheel makes a longer patch.
TEST(ContactPatchSection, HertzSizeFollowsTheWheel) {
  const auto length = [](double radius) {
    const Scene scene = parse_scene("[joint]\ngap = 0.006\n[wheel]\nradius = " + std::to_string(radius) +
                                        "\n[contact_patch]\nsize = \"hertz\"\ncrown_radius = 0.3\n",
                                    "t.toml", {}, SceneCheck::keys_only);
    return local_model_inputs_of(scene).patch.length_m;
  };
  EXPECT_GT(length(0.6), length(0.4));
}

TEST(ContactPatchSection, ZeroGapIsAnInputErrorOfThePressureModelOnly) {
  const Scene scene = parse_scene("[joint]\ngap = 0.0\n", "t.toml", {}, SceneCheck::keys_only);
  try {
    local_model_inputs_of(scene);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "t.toml");
    EXPECT_EQ(error.key(), "joint.gap");
  }
}

// shape = "solved": its keys reach the solver's settings, 100 steps by
// default, elastic without yield_pressure; the prescribed-patch keys refused.
TEST(ContactPatchSection, SolvedKeysReachTheSolver) {
  const Scene elastic = parse_scene("[joint]\ngap = 0.006\ncrown_radius = 0.3\n[contact_patch]\nshape = \"solved\"\n",
                                    "t.toml", {}, SceneCheck::keys_only);
  EXPECT_TRUE(elastic.contact_patch.solved);
  EXPECT_EQ(elastic.contact_patch.steps, 100);
  EXPECT_FALSE(elastic.contact_patch.solved_contact.yield_pressure_Pa.has_value());
  EXPECT_EQ(elastic.contact_patch.solved_contact.edge_average_length_m, 1e-3);
  const Scene edge = parse_scene(
      "[joint]\ngap = 0.006\n[contact_patch]\nshape = \"solved\"\nedge_average_length = 5e-4\n", "t.toml", {},
      SceneCheck::keys_only);
  EXPECT_EQ(edge.contact_patch.solved_contact.edge_average_length_m, 5e-4);
  const Scene capped = parse_scene(
      "[joint]\ngap = 0.006\ncrown_radius = 0.3\n[contact_patch]\nshape = \"solved\"\nyield_pressure = 1.15e9\n"
      "height_mismatch = 1e-4\ncells_x = 64\ncells_y = 48\nsteps = 7\n",
      "t.toml", {}, SceneCheck::keys_only);
  const RailEndContactSettings& s = capped.contact_patch.solved_contact;
  EXPECT_EQ(*s.yield_pressure_Pa, 1.15e9);
  EXPECT_EQ(s.height_mismatch_m, 1e-4);
  EXPECT_EQ(s.cells_x, 64);
  EXPECT_EQ(s.cells_y, 48);
  EXPECT_EQ(capped.contact_patch.steps, 7);
}

// contact_patch.window_over_axes: given, the grid keeps it (a patch reaching
// its border is refused); absent, 2.5 Hertz axes that grow where a patch
// reaches the border (SolvedForcesCli.AWindowTheWheelsTwoPatchesOutgrow...).
TEST(ContactPatchSection, AGivenWindowIsKeptAndOnlyAnAbsentOneGrows) {
  const std::string solved = "[joint]\ngap = 0.006\ncrown_radius = 0.3\n[contact_patch]\nshape = \"solved\"\n";
  const Scene by_default = parse_scene(solved, "t.toml", {}, SceneCheck::keys_only);
  EXPECT_TRUE(by_default.contact_patch.grow_window);
  EXPECT_EQ(by_default.contact_patch.solved_contact.window_over_axes, 2.5);
  const Scene given = parse_scene(solved + "window_over_axes = 4\n", "t.toml", {}, SceneCheck::keys_only);
  EXPECT_FALSE(given.contact_patch.grow_window);
  EXPECT_EQ(given.contact_patch.solved_contact.window_over_axes, 4.0);
  const auto refusal = [](const std::string& text) {
    try {
      parse_scene(text, "t.toml", {}, SceneCheck::keys_only);
    } catch (const InputError& error) {
      std::printf("%s\n", error.what());
      return error.key();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal(solved + "window_over_axes = 1.4\n"), "contact_patch.window_over_axes");
  EXPECT_EQ(refusal(solved + "window_over_axes = 21\n"), "contact_patch.window_over_axes");
  EXPECT_EQ(refusal("[joint]\ngap = 0.006\n[contact_patch]\nwindow_over_axes = 3\n"), "contact_patch.window_over_axes");
}

TEST(ContactPatchSection, SolvedRefusesWhatDoesNotApply) {
  const auto key_of = [](const std::string& section) {
    try {
      parse_scene("[joint]\ngap = 0.006\n[contact_patch]\n" + section, "t.toml", {}, SceneCheck::keys_only);
    } catch (const InputError& error) {
      std::printf("%s\n", error.what());
      return error.key();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(key_of("shape = \"solved\"\nlength = 0.01\n"), "contact_patch.length");
  EXPECT_EQ(key_of("yield_pressure = 1e9\n"), "contact_patch.yield_pressure");
  EXPECT_EQ(key_of("shape = \"solved\"\nyield_pressure = 1e7\n"), "contact_patch.yield_pressure");  // below 100 MPa
  // The edge pressure's length: elastic only, 1e-5 to 5e-3 m.
  EXPECT_EQ(key_of("edge_average_length = 1e-3\n"), "contact_patch.edge_average_length");
  EXPECT_EQ(key_of("shape = \"solved\"\nyield_pressure = 1.15e9\nedge_average_length = 1e-3\n"),
            "contact_patch.edge_average_length");
  EXPECT_EQ(key_of("shape = \"solved\"\nedge_average_length = 0.01\n"), "contact_patch.edge_average_length");
  EXPECT_EQ(key_of("shape = \"solved\"\nedge_average_length = 0\n"), "contact_patch.edge_average_length");
}

}  // namespace
}  // namespace railjoint
