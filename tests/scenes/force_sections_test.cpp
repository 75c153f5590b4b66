// The [contact], [track] and [vehicle] sections (scenes/force_sections.h)
// and the [sim] keys each run reads: defaults, each switch and what it fills
// in, and every combination that would change nothing or cannot run refused
// by the key the user typed.

#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "scenes/scene_file.h"
#include "sim/force_setting_ranges.h"
#include "sim/setting_checks.h"
#include "sim/setting_ranges.h"
#include "support/input_error.h"

namespace railjoint {
namespace {

const char* kScene = R"(
[joint]
theta_deg = 30.0
[wheel]
y = 0.015
)";

Scene scene_with(const std::vector<std::string>& overrides) { return parse_scene(kScene, "test.toml", overrides); }

struct Refusal {
  std::string key;      // InputError::key()
  std::string message;  // InputError::message()
  std::string what;     // the one line the CLI prints
};

Refusal refusal(const std::vector<std::string>& overrides) {
  try {
    parse_scene(kScene, "test.toml", overrides);
  } catch (const InputError& error) {
    std::printf("%s\n", error.what());
    return {error.key(), error.message(), error.what()};
  }
  std::printf("(accepted)\n");
  return {};
}

const std::vector<std::string> kInertial = {"sim.mode=inertial"};

std::vector<std::string> inertial(std::vector<std::string> more) {
  more.insert(more.begin(), "sim.mode=inertial");
  return more;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ForceSections, AbsentSectionsAreARigidContactWithoutForceModel) {
  for (const Scene& scene : {scene_with({}), scene_with(kInertial)}) {
    std::printf("%s mode, no [contact]: force run %s, contact stiffness %s\n",
                scene.sim.mode() == SimMode::inertial ? "inertial" : "kinematic", scene.sim.elastic() ? "set" : "empty",
                scene.sim.linear_contact() ? "set" : "empty");
    EXPECT_FALSE((scene.sim.elastic() != nullptr));
    EXPECT_FALSE((scene.sim.linear_contact() != nullptr));
  }
  // law = "rigid" said out loud is the same.
  const Scene rigid = scene_with(inertial({"contact.law=rigid", "track.model=rigid", "vehicle.model=load"}));
  EXPECT_FALSE((rigid.sim.elastic() != nullptr));
  EXPECT_FALSE((rigid.sim.linear_contact() != nullptr));
}

TEST(ForceSections, LinearLawSetsTheContactSpring) {
  const Scene defaults = scene_with(inertial({"contact.law=linear"}));
  ASSERT_TRUE((defaults.sim.linear_contact() != nullptr));
  std::printf("linear law defaults: stiffness %g N/m, damping %g N s/m\n",
              defaults.sim.linear_contact()->stiffness_N_per_m, defaults.sim.linear_contact()->damping_N_s_per_m);
  // The documented default: the textbook linearised Hertz stiffness at 100 kN.
  EXPECT_DOUBLE_EQ(defaults.sim.linear_contact()->stiffness_N_per_m, 1.4e9);
  // Issue 29, item 3: undamped (the old default) the wheel bounced on the
  // rigid track beyond any run-out. Critical for the default wheel (750 kg):
  // 2 sqrt(1.4e9 N/m x 750 kg) = 2 x 1.0247e6 = 2.0494e6 N s/m.
  EXPECT_NEAR(defaults.sim.linear_contact()->damping_N_s_per_m, 2.0494e6, 0.0001e6);
  const Scene heavy = scene_with(inertial({"contact.law=linear", "wheel.mass=3000"}));
  EXPECT_NEAR(heavy.sim.linear_contact()->damping_N_s_per_m, 2.0 * defaults.sim.linear_contact()->damping_N_s_per_m,
              1e-6);
  EXPECT_DOUBLE_EQ(
      scene_with(inertial({"contact.law=linear", "contact.damping=0"})).sim.linear_contact()->damping_N_s_per_m, 0.0);
  EXPECT_FALSE((defaults.sim.elastic() != nullptr));

  const Scene given = scene_with(inertial({"contact.law=linear", "contact.stiffness=2e9", "contact.damping=500"}));
  ASSERT_TRUE((given.sim.linear_contact() != nullptr));
  EXPECT_DOUBLE_EQ(given.sim.linear_contact()->stiffness_N_per_m, 2e9);
  EXPECT_DOUBLE_EQ(given.sim.linear_contact()->damping_N_s_per_m, 500.0);
}

TEST(ForceSections, HertzLawMakesAForceRun) {
  const Scene scene = scene_with(inertial({"contact.law=hertz"}));
  ASSERT_TRUE((scene.sim.elastic() != nullptr));
  const ElasticCrossingSettings& e = *scene.sim.elastic();
  std::printf("hertz law defaults: restitution %g, hertz constant %s, track %s, vehicle %s\n", e.contact.restitution,
              e.contact.hertz_constant_m_per_N2_3 ? "given" : "empty", e.track ? "lumped" : "rigid",
              e.vehicle ? "sprung" : "load");
  EXPECT_DOUBLE_EQ(e.contact.restitution, 1.0);  // pure Hertz, Jenkins's model
  EXPECT_FALSE(e.contact.hertz_constant_m_per_N2_3.has_value());  // the new-wheel formula at the wheel's radius
  EXPECT_FALSE(e.track.has_value());
  EXPECT_FALSE(e.vehicle.has_value());
  EXPECT_FALSE((scene.sim.linear_contact() != nullptr));

  const Scene given = scene_with(
      inertial({"contact.law=hertz", "contact.hertz_constant=4.5e-8", "contact.restitution=0.6", "sim.force_time_step=1e-6"}));
  ASSERT_TRUE((given.sim.elastic() != nullptr));
  ASSERT_TRUE(given.sim.elastic()->contact.hertz_constant_m_per_N2_3.has_value());
  EXPECT_DOUBLE_EQ(*given.sim.elastic()->contact.hertz_constant_m_per_N2_3, 4.5e-8);
  EXPECT_DOUBLE_EQ(given.sim.elastic()->contact.restitution, 0.6);
  EXPECT_DOUBLE_EQ(given.sim.inertial()->force_time_step_s, 1e-6);
}

// The documented defaults (sim/elastic_track_settings.h, sim/DESIGN.md "Forces on
// an elastic track"): a 0.6 m bay of 60.2 kg/m rail = 36.12 kg on a 200 MN/m,
// 28 kN s/m pad, a 140 kg half sleeper on 40 MN/m, 47 kN s/m ballast.
TEST(ForceSections, LumpedTrackHasTheDocumentedDefaultsAndTakesEachKey) {
  const Scene scene = scene_with(inertial({"contact.law=hertz", "track.model=lumped"}));
  ASSERT_TRUE((scene.sim.elastic() != nullptr));
  ASSERT_TRUE(scene.sim.elastic()->track.has_value());
  const LumpedTrackSettings& t = *scene.sim.elastic()->track;
  std::printf("lumped track defaults: rail %g kg, pad %g N/m %g N s/m, sleeper %g kg, ballast %g N/m %g N s/m\n",
              t.rail_mass_kg, t.support.pad_stiffness_N_per_m, t.support.pad_damping_N_s_per_m, t.support.sleeper_mass_kg,
              t.support.ballast_stiffness_N_per_m, t.support.ballast_damping_N_s_per_m);
  EXPECT_NEAR(t.rail_mass_kg, 36.12, 1e-12);  // 60.2 x 0.6 in binary: a few ulp off 36.12
  EXPECT_DOUBLE_EQ(t.support.pad_stiffness_N_per_m, 200e6);
  EXPECT_DOUBLE_EQ(t.support.pad_damping_N_s_per_m, 28e3);
  EXPECT_DOUBLE_EQ(t.support.sleeper_mass_kg, 140.0);
  EXPECT_DOUBLE_EQ(t.support.ballast_stiffness_N_per_m, 40e6);
  EXPECT_DOUBLE_EQ(t.support.ballast_damping_N_s_per_m, 47e3);
  EXPECT_FALSE(scene.sim.elastic()->vehicle.has_value());

  const Scene given = scene_with(inertial({"contact.law=hertz", "track.model=lumped", "track.rail_mass=50",
                                           "track.pad_stiffness=3e8", "track.pad_damping=1e4", "track.sleeper_mass=150",
                                           "track.ballast_stiffness=5e7", "track.ballast_damping=6e4"}));
  ASSERT_TRUE(given.sim.elastic() && given.sim.elastic()->track);
  const LumpedTrackSettings& g = *given.sim.elastic()->track;
  EXPECT_DOUBLE_EQ(g.rail_mass_kg, 50.0);
  EXPECT_DOUBLE_EQ(g.support.pad_stiffness_N_per_m, 3e8);
  EXPECT_DOUBLE_EQ(g.support.pad_damping_N_s_per_m, 1e4);
  EXPECT_DOUBLE_EQ(g.support.sleeper_mass_kg, 150.0);
  EXPECT_DOUBLE_EQ(g.support.ballast_stiffness_N_per_m, 5e7);
  EXPECT_DOUBLE_EQ(g.support.ballast_damping_N_s_per_m, 6e4);
}

TEST(ForceSections, SprungVehicle) {
  const Scene scene = scene_with(inertial({"contact.law=hertz", "vehicle.model=sprung"}));
  ASSERT_TRUE(scene.sim.elastic() && scene.sim.elastic()->vehicle);
  const PrimarySuspensionSettings& s = *scene.sim.elastic()->vehicle;
  std::printf("sprung defaults: primary %g N/m, %g N s/m, sprung mass %s\n", s.primary_stiffness_N_per_m,
              s.primary_damping_N_s_per_m, s.sprung_mass_kg ? "given" : "empty (wheel_load / g)");
  EXPECT_FALSE(s.sprung_mass_kg.has_value());  // the wheel load's mass
  EXPECT_FALSE(scene.sim.elastic()->track.has_value());

  const Scene given = scene_with(inertial({"contact.law=hertz", "vehicle.model=sprung", "vehicle.sprung_mass=8000",
                                           "vehicle.primary_stiffness=2e6", "vehicle.primary_damping=2e4"}));
  ASSERT_TRUE(given.sim.elastic() && given.sim.elastic()->vehicle);
  const PrimarySuspensionSettings& g = *given.sim.elastic()->vehicle;
  ASSERT_TRUE(g.sprung_mass_kg.has_value());
  EXPECT_DOUBLE_EQ(*g.sprung_mass_kg, 8000.0);
  EXPECT_DOUBLE_EQ(g.primary_stiffness_N_per_m, 2e6);
  EXPECT_DOUBLE_EQ(g.primary_damping_N_s_per_m, 2e4);
  // A sprung mass given: a wheel load of 0 is fine.
  EXPECT_EQ(refusal(inertial({"contact.law=hertz", "vehicle.model=sprung", "sim.wheel_load=0",
                              "vehicle.sprung_mass=8000"}))
                .key,
            "");
}

TEST(ForceSections, TheOldContactKeysNameTheirNewPlace) {
  for (const char* key : {"sim.contact_stiffness", "sim.contact_damping"}) {
    for (const std::vector<std::string>& mode : {std::vector<std::string>{}, kInertial}) {
      std::vector<std::string> overrides = mode;
      overrides.push_back(std::string(key) + "=1e9");
      const Refusal r = refusal(overrides);
      EXPECT_EQ(r.key, key);
      EXPECT_TRUE(contains(r.message, "has moved to the [contact] section")) << r.message;
    }
  }
}

TEST(ForceSections, AForceModelNeedsTheInertialMode) {
  for (const char* law : {"hertz", "linear"}) {
    const Refusal r = refusal({std::string("contact.law=") + law});
    EXPECT_EQ(r.key, "contact.law");
    EXPECT_TRUE(contains(r.message, "only applies to sim.mode = \"inertial\"")) << r.message;
  }
  EXPECT_EQ(refusal({"track.model=lumped"}).key, "track.model");
  EXPECT_EQ(refusal({"vehicle.model=sprung"}).key, "vehicle.model");
  // In the kinematic mode sim.force_time_step is one of the inertial mode's keys.
  EXPECT_EQ(refusal({"sim.force_time_step=1e-6"}).key, "sim.force_time_step");
}

TEST(ForceSections, TrackAndVehicleModelsNeedTheHertzLaw) {
  for (const char* law : {"rigid", "linear"}) {
    Refusal r = refusal(inertial({std::string("contact.law=") + law, "track.model=lumped"}));
    EXPECT_EQ(r.key, "track.model");
    EXPECT_TRUE(contains(r.message, "needs contact.law = \"hertz\"")) << r.message;
    r = refusal(inertial({std::string("contact.law=") + law, "vehicle.model=sprung"}));
    EXPECT_EQ(r.key, "vehicle.model");
    EXPECT_TRUE(contains(r.message, "needs contact.law = \"hertz\"")) << r.message;
  }
  // contact.law absent is rigid.
  EXPECT_EQ(refusal(inertial({"track.model=lumped"})).key, "track.model");
}

TEST(ForceSections, KeysOfAnotherSwitchAreRefused) {
  Refusal r = refusal(inertial({"contact.law=hertz", "contact.stiffness=1e9"}));
  EXPECT_EQ(r.key, "contact.stiffness");
  EXPECT_TRUE(contains(r.message, "contact.law = \"linear\"")) << r.message;
  EXPECT_EQ(refusal(inertial({"contact.law=hertz", "contact.damping=10"})).key, "contact.damping");
  r = refusal(inertial({"contact.law=linear", "contact.restitution=0.5"}));
  EXPECT_EQ(r.key, "contact.restitution");
  EXPECT_TRUE(contains(r.message, "contact.law = \"hertz\"")) << r.message;
  r = refusal(inertial({"contact.law=hertz", "track.rail_mass=50"}));  // track.model absent: rigid
  EXPECT_EQ(r.key, "track.rail_mass");
  EXPECT_TRUE(contains(r.message, "track.model = \"lumped\"")) << r.message;
  r = refusal(inertial({"contact.law=hertz", "track.model=rigid", "track.rail_mass=50"}));
  EXPECT_EQ(r.key, "track.rail_mass");
  r = refusal(inertial({"contact.law=hertz", "vehicle.sprung_mass=8000"}));
  EXPECT_EQ(r.key, "vehicle.sprung_mass");
  EXPECT_TRUE(contains(r.message, "vehicle.model = \"sprung\"")) << r.message;
}

TEST(ForceSections, RigidContactSwitchesAreRefusedInAForceRun) {
  Refusal r = refusal(inertial({"contact.law=hertz", "sim.friction=0.2"}));
  EXPECT_EQ(r.key, "sim.friction");
  EXPECT_TRUE(contains(r.message, "does not apply with contact.law = \"hertz\"")) << r.message;
  r = refusal(inertial({"contact.law=hertz", "sim.restitution=0.5"}));
  EXPECT_EQ(r.key, "sim.restitution");
  EXPECT_TRUE(contains(r.message, "contact.restitution")) << r.message;  // where its dissipation is
  EXPECT_EQ(refusal(inertial({"contact.law=hertz", "sim.horizontal=free"})).key, "sim.horizontal");
  // The same friction without the Hertz law is read.
  EXPECT_DOUBLE_EQ(scene_with(inertial({"sim.friction=0.2"})).sim.friction, 0.2);
}

// The rigid solver's numerical keys and the flat approach change nothing in
// a force run (its own step, the exact narrow phase, a static start on the
// slope): each is refused by name, as the review found them accepted.
TEST(ForceSections, RigidSolverKeysAndTheFlatApproachAreRefusedInAForceRun) {
  for (const char* key : {"sim.time_step=1e-5", "sim.refined_time_step=1e-7", "sim.slop=1e-7", "sim.hard_contacts=false",
                          "sim.narrow_phase=bullet", "sim.internal_edge_fix=false", "sim.solver_iterations=10",
                          "sim.flat_approach=0.5"}) {
    const std::string assignment = key;
    const Refusal r = refusal(inertial({"contact.law=hertz", assignment}));
    EXPECT_EQ(r.key, assignment.substr(0, assignment.find('='))) << r.what;
    EXPECT_TRUE(contains(r.message, "does not apply with contact.law = \"hertz\"")) << r.message;
  }
  // Without the Hertz law they are read as before.
  EXPECT_DOUBLE_EQ(scene_with(inertial({"sim.flat_approach=0.5"})).sim.inertial()->flat_approach_m, 0.5);
  // The rest of the rigid runs' [sim] keys, which had no test: a force run
  // refuses every [sim] key it does not read.
  for (const char* key : {"sim.refine_distance=1e-5", "sim.refine_hold=1e-5", "sim.margin=1e-4",
                          "sim.contact_processing_threshold=0.001", "sim.split_impulse_threshold=-0.01"}) {
    const std::string assignment = key;
    const Refusal r = refusal(inertial({"contact.law=hertz", assignment}));
    EXPECT_EQ(r.key, assignment.substr(0, assignment.find('='))) << r.what;
    EXPECT_TRUE(contains(r.message, "(Bullet solves no contact)")) << r.message;
  }
  // What it does read: where the wheel starts and ends, the contact's reach
  // and the thin disc's stand-in width.
  const Scene read = scene_with(inertial({"contact.law=hertz", "sim.approach_distance=0.2", "sim.run_out_time=0.03",
                                          "sim.contact_breaking_threshold=0.03", "sim.disc_half_width=0.002",
                                          "sim.wheel_load=1e5", "sim.force_time_step=2e-6"}));
  EXPECT_DOUBLE_EQ(read.sim.contact_breaking_threshold_m, 0.03);
  EXPECT_DOUBLE_EQ(read.sim.disc_half_width_m, 0.002);
}

TEST(ForceSections, DiscreteTrackTakesItsKeys) {
  const Scene scene = scene_with(inertial({"contact.law=hertz", "track.model=discrete", "track.bending_stiffness=5e6",
                                           "track.mass_per_length=54", "track.sleeper_spacing=0.65",
                                           "track.joint_bending_stiffness=0"}));
  ASSERT_TRUE(scene.sim.elastic() && scene.sim.elastic()->discrete_track);
  EXPECT_FALSE(scene.sim.elastic()->track.has_value());
  const DiscreteTrackSettings& t = *scene.sim.elastic()->discrete_track;
  EXPECT_DOUBLE_EQ(t.bending_stiffness_N_m2, 5e6);
  EXPECT_DOUBLE_EQ(t.mass_per_length_kg_per_m, 54.0);
  EXPECT_DOUBLE_EQ(t.sleeper_spacing_m, 0.65);
  ASSERT_TRUE(t.joint_bending_stiffness_N_m_per_rad.has_value());
  EXPECT_DOUBLE_EQ(*t.joint_bending_stiffness_N_m_per_rad, 0.0);
  // Absent: continuous rail through the joint.
  EXPECT_FALSE(scene_with(inertial({"contact.law=hertz", "track.model=discrete"}))
                   .sim.elastic()
                   ->discrete_track->joint_bending_stiffness_N_m_per_rad.has_value());
  EXPECT_EQ(refusal(inertial({"contact.law=hertz", "track.model=lumped", "track.sleeper_spacing=0.6"})).key,
            "track.sleeper_spacing");
  EXPECT_EQ(refusal(inertial({"contact.law=hertz", "track.model=discrete", "track.rail_mass=50"})).key,
            "track.rail_mass");
}

// track.beam: Euler's rail by default; "timoshenko" adds the shear and the
// rotary inertia with 60E1's defaults (elastic_track_settings.h), each key
// its own; the keys are refused with Euler's rail, the beam with another
// track, a value out of range by its key.
TEST(ForceSections, TheDiscreteTracksBeamTakesItsKeys) {
  const std::vector<std::string> discrete = {"contact.law=hertz", "track.model=discrete"};
  EXPECT_FALSE(scene_with(inertial(discrete)).sim.elastic()->discrete_track->timoshenko.has_value());
  std::vector<std::string> typed = inertial(discrete);
  typed.push_back("track.beam=timoshenko");
  const std::optional<TimoshenkoRailSettings> defaults = scene_with(typed).sim.elastic()->discrete_track->timoshenko;
  ASSERT_TRUE(defaults.has_value());
  EXPECT_DOUBLE_EQ(defaults->shear_modulus_Pa, 81e9);
  EXPECT_DOUBLE_EQ(defaults->shear_coefficient, 0.4);
  EXPECT_DOUBLE_EQ(defaults->section_area_m2, 7.670e-3);
  EXPECT_DOUBLE_EQ(defaults->rotary_inertia_kg_m, 0.2385);
  for (const char* key : {"track.shear_modulus=8e10", "track.shear_coefficient=0.5", "track.section_area=7e-3",
                          "track.rotary_inertia=0.2"}) {
    typed.push_back(key);
  }
  const TimoshenkoRailSettings given = *scene_with(typed).sim.elastic()->discrete_track->timoshenko;
  EXPECT_DOUBLE_EQ(given.shear_modulus_Pa, 8e10);
  EXPECT_DOUBLE_EQ(given.shear_coefficient, 0.5);
  EXPECT_DOUBLE_EQ(given.section_area_m2, 7e-3);
  EXPECT_DOUBLE_EQ(given.rotary_inertia_kg_m, 0.2);

  const Refusal euler = refusal(inertial({"contact.law=hertz", "track.model=discrete", "track.shear_modulus=8e10"}));
  EXPECT_EQ(euler.key, "track.shear_modulus");
  EXPECT_TRUE(contains(euler.message, "only applies with track.beam = \"timoshenko\"")) << euler.what;
  const Refusal lumped = refusal(inertial({"contact.law=hertz", "track.model=lumped", "track.beam=timoshenko"}));
  EXPECT_EQ(lumped.key, "track.beam");
  EXPECT_TRUE(contains(lumped.message, "only applies with track.model = \"discrete\"")) << lumped.what;
  // A shear key under another track: the key, typed after the model, is blamed.
  EXPECT_EQ(refusal(inertial({"contact.law=hertz", "track.model=lumped", "track.shear_coefficient=0.3"})).key,
            "track.shear_coefficient");
  const Refusal range =
      refusal(inertial({"contact.law=hertz", "track.model=discrete", "track.beam=timoshenko", "track.shear_coefficient=0"}));
  EXPECT_EQ(range.key, "track.shear_coefficient");
  EXPECT_EQ(refusal(inertial({"contact.law=hertz", "track.model=discrete", "track.beam=bernoulli"})).key, "track.beam");
  // A damped contact runs on both rails: a Timoshenko rail's damper reads
  // the local shear's rate with the force (elastic_crossing_run.cpp,
  // tests/sim/timoshenko_rail_test.cpp).
  const Scene damped =
      scene_with(inertial({"contact.law=hertz", "track.model=discrete", "track.beam=timoshenko", "contact.restitution=0.5"}));
  EXPECT_NO_THROW(check_sim_settings(damped.sim, damped.joint, damped.wheel));
  const Scene euler_damped = scene_with(inertial({"contact.law=hertz", "track.model=discrete", "contact.restitution=0.5"}));
  EXPECT_NO_THROW(check_sim_settings(euler_damped.sim, euler_damped.joint, euler_damped.wheel));
}

TEST(ForceSections, ForceTimeStepOnlyWithTheHertzLaw) {
  for (const char* law : {"rigid", "linear"}) {
    const Refusal r = refusal(inertial({std::string("contact.law=") + law, "sim.force_time_step=1e-6"}));
    EXPECT_EQ(r.key, "sim.force_time_step");
    EXPECT_TRUE(contains(r.message, "only applies with contact.law = \"hertz\"")) << r.message;
  }
  EXPECT_EQ(refusal(inertial({"sim.force_time_step=1e-6"})).key, "sim.force_time_step");
}

TEST(ForceSections, UnknownChoicesNameTheKey) {
  Refusal r = refusal(inertial({"contact.law=elastic"}));
  EXPECT_EQ(r.key, "contact.law");
  EXPECT_TRUE(contains(r.message, "must be one of \"rigid\", \"linear\", \"hertz\", got \"elastic\"")) << r.message;
  EXPECT_EQ(refusal(inertial({"contact.law=hertz", "track.model=slab"})).key, "track.model");
  EXPECT_EQ(refusal(inertial({"contact.law=hertz", "vehicle.model=bogie"})).key, "vehicle.model");
  // A typo in a section is an unknown key, not a silent default.
  r = refusal(inertial({"contact.law=hertz", "contact.restitutoin=0.5"}));
  EXPECT_EQ(r.key, "contact.restitutoin");
}

// A typo of a key the section takes only sometimes (left out, or under
// another switch) is named as one: the reader suggested only the keys it
// had read, so `hertz_constnt` got no suggestion and
// `joint_bending_stifness` was offered `bending_stiffness`.
TEST(ForceSections, ATypoOfAnOptionalOrSwitchedKeyIsNamed) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> typos = {
      {inertial({"contact.law=hertz", "contact.hertz_constnt=4e-8"}), "hertz_constant"},
      {inertial({"contact.law=linear", "contact.dampng=10"}), "damping"},
      {inertial({"contact.law=hertz", "track.pad_stifness=1e8"}), "pad_stiffness"},
      {inertial({"contact.law=hertz", "track.model=discrete", "track.joint_bending_stifness=0"}),
       "joint_bending_stiffness"},
      {inertial({"contact.law=hertz", "vehicle.sprung_mas=500"}), "sprung_mass"},
      {inertial({"contact.law=hertz", "track.model=discrete", "vehicle.model=bogie", "vehicle.body_mas=1e4"}),
       "body_mass"},
      {inertial({"sim.run_out_tim=0.01"}), "run_out_time"},
      {{"sim.refine_hol=1e-5"}, "refine_hold"},
      {{"sim.wheel_lod=1e5"}, "wheel_load"},
  };
  for (const auto& [overrides, meant] : typos) {
    const Refusal r = refusal(overrides);
    EXPECT_TRUE(contains(r.message, "unknown key")) << r.what;
    EXPECT_TRUE(contains(r.message, "(did you mean '" + meant + "'?)")) << r.what;
  }
}

TEST(ForceSections, SprungVehicleWithoutWheelLoadNeedsItsMass) {
  const Refusal r = refusal(inertial({"contact.law=hertz", "vehicle.model=sprung", "sim.wheel_load=0"}));
  EXPECT_EQ(r.key, "vehicle.model");
  EXPECT_TRUE(contains(r.message, "needs vehicle.sprung_mass")) << r.message;
}


// "must be in [lo, hi] unit, got x" as numbers: the reader prints ten
// digits (1000000), the checks six (1e+06).
struct RangeText {
  char open = 0, close = 0;
  double lo = 0.0, hi = 0.0, got = 0.0;
  std::string unit;
  bool operator==(const RangeText&) const = default;
};

RangeText range_text(const std::string& message) {
  RangeText r;
  const std::size_t start = message.find("must be in ");
  if (start == std::string::npos) return r;
  const std::size_t open = start + std::string("must be in ").size();
  const std::size_t comma = message.find(", ", open);
  const std::size_t close = message.find_first_of("])", comma);
  const std::size_t got = message.find(", got ", close);
  if (comma == std::string::npos || close == std::string::npos || got == std::string::npos) return r;
  r.open = message[open];
  r.close = message[close];
  r.lo = std::stod(message.substr(open + 1, comma - open - 1));
  r.hi = std::stod(message.substr(comma + 2, close - comma - 2));
  r.unit = message.substr(close + 1, got - close - 1);
  r.got = std::stod(message.substr(got + 6));
  return r;
}

// The settings `built` from `scene`'s, refused by check_sim_settings as the
// reader refused the typed value (`read`): the same key, the same range.
void expect_the_same_refusal(const SimSettings& built, const Scene& scene, const std::string& key, const Refusal& read) {
  Refusal checked;
  try {
    check_sim_settings(built, scene.joint, scene.wheel);
  } catch (const InputError& error) {
    std::printf("built in code: %s\n", error.what());
    checked = {error.key(), error.message(), error.what()};
  }
  EXPECT_EQ(read.key, key);
  EXPECT_EQ(checked.key, key);
  EXPECT_NE(range_text(read.message).open, 0) << read.what;
  EXPECT_TRUE(range_text(checked.message) == range_text(read.message)) << checked.message << " vs " << read.message;
}

// Each [contact], [track] and [vehicle] key's range is written once
// (sim/force_setting_ranges.h): a value out of it is refused alike whether
// typed in a scene (by the reader, with the file) or built in code (by
// check_sim_settings), with the same key and the same range. The values are
// outside anything physical (a 50 m wheelbase, a 0.5 kg rail, a negative
// damping, a Poisson ratio of 0.5), so the test does not restate a bound.
TEST(ForceSections, AKeysRangeIsTheSameForTheReaderAndTheChecks) {
  struct Case {
    std::vector<std::string> switches;
    std::string assignment;  // section.key=value
    std::function<void(ElasticCrossingSettings&, double)> set;
  };
  const std::vector<std::string> hertz = {"contact.law=hertz"};
  const std::vector<std::string> lumped = {"contact.law=hertz", "track.model=lumped"};
  const std::vector<std::string> discrete = {"contact.law=hertz", "track.model=discrete"};
  const std::vector<std::string> sprung = {"contact.law=hertz", "vehicle.model=sprung"};
  const std::vector<std::string> bogie = {"contact.law=hertz", "track.model=discrete", "vehicle.model=bogie"};
  const std::vector<std::string> timoshenko = {"contact.law=hertz", "track.model=discrete", "track.beam=timoshenko"};
  const std::vector<Case> cases = {
      {timoshenko, "track.shear_modulus=1e8",
       [](ElasticCrossingSettings& e, double x) { e.discrete_track->timoshenko->shear_modulus_Pa = x; }},
      {timoshenko, "track.shear_coefficient=0",
       [](ElasticCrossingSettings& e, double x) { e.discrete_track->timoshenko->shear_coefficient = x; }},
      {timoshenko, "track.section_area=2",
       [](ElasticCrossingSettings& e, double x) { e.discrete_track->timoshenko->section_area_m2 = x; }},
      {timoshenko, "track.rotary_inertia=1e-4",
       [](ElasticCrossingSettings& e, double x) { e.discrete_track->timoshenko->rotary_inertia_kg_m = x; }},
      {hertz, "contact.youngs_modulus=1e14", [](ElasticCrossingSettings& e, double x) { e.contact.youngs_modulus_Pa = x; }},
      {hertz, "contact.poisson_ratio=0.5", [](ElasticCrossingSettings& e, double x) { e.contact.poisson_ratio = x; }},
      {hertz, "contact.hertz_constant=1e-3",
       [](ElasticCrossingSettings& e, double x) { e.contact.hertz_constant_m_per_N2_3 = x; }},
      {hertz, "contact.restitution=1.5", [](ElasticCrossingSettings& e, double x) { e.contact.restitution = x; }},
      {lumped, "track.rail_mass=0.5", [](ElasticCrossingSettings& e, double x) { e.track->rail_mass_kg = x; }},
      {lumped, "track.pad_stiffness=10",
       [](ElasticCrossingSettings& e, double x) { e.track->support.pad_stiffness_N_per_m = x; }},
      {lumped, "track.pad_damping=-1",
       [](ElasticCrossingSettings& e, double x) { e.track->support.pad_damping_N_s_per_m = x; }},
      {lumped, "track.sleeper_mass=0.5", [](ElasticCrossingSettings& e, double x) { e.track->support.sleeper_mass_kg = x; }},
      {discrete, "track.ballast_stiffness=10",
       [](ElasticCrossingSettings& e, double x) { e.discrete_track->support.ballast_stiffness_N_per_m = x; }},
      {discrete, "track.ballast_damping=-1",
       [](ElasticCrossingSettings& e, double x) { e.discrete_track->support.ballast_damping_N_s_per_m = x; }},
      {discrete, "track.bending_stiffness=10",
       [](ElasticCrossingSettings& e, double x) { e.discrete_track->bending_stiffness_N_m2 = x; }},
      {discrete, "track.mass_per_length=0.5",
       [](ElasticCrossingSettings& e, double x) { e.discrete_track->mass_per_length_kg_per_m = x; }},
      {discrete, "track.sleeper_spacing=50",
       [](ElasticCrossingSettings& e, double x) { e.discrete_track->sleeper_spacing_m = x; }},
      {discrete, "track.joint_bending_stiffness=-1",
       [](ElasticCrossingSettings& e, double x) { e.discrete_track->joint_bending_stiffness_N_m_per_rad = x; }},
      {sprung, "vehicle.sprung_mass=0.5", [](ElasticCrossingSettings& e, double x) { e.vehicle->sprung_mass_kg = x; }},
      {sprung, "vehicle.primary_stiffness=1",
       [](ElasticCrossingSettings& e, double x) { e.vehicle->primary_stiffness_N_per_m = x; }},
      {sprung, "vehicle.primary_damping=-1",
       [](ElasticCrossingSettings& e, double x) { e.vehicle->primary_damping_N_s_per_m = x; }},
      {bogie, "vehicle.axle_spacing=50", [](ElasticCrossingSettings& e, double x) { e.bogie->axle_spacing_m = x; }},
      {bogie, "vehicle.frame_mass=0.5", [](ElasticCrossingSettings& e, double x) { e.bogie->frame_mass_kg = x; }},
      {bogie, "vehicle.frame_pitch_inertia=0.5",
       [](ElasticCrossingSettings& e, double x) { e.bogie->frame_pitch_inertia_kg_m2 = x; }},
      {bogie, "vehicle.body_mass=0.5", [](ElasticCrossingSettings& e, double x) { e.bogie->body_mass_kg = x; }},
      {bogie, "vehicle.primary_damping=-1",
       [](ElasticCrossingSettings& e, double x) { e.bogie->primary_damping_N_s_per_m = x; }},
      {bogie, "vehicle.secondary_stiffness=-1",
       [](ElasticCrossingSettings& e, double x) { e.bogie->secondary_stiffness_N_per_m = x; }},
      {bogie, "vehicle.secondary_damping=-1",
       [](ElasticCrossingSettings& e, double x) { e.bogie->secondary_damping_N_s_per_m = x; }},
  };
  for (const Case& c : cases) {
    const std::string key = c.assignment.substr(0, c.assignment.find('='));
    const double value = std::stod(c.assignment.substr(c.assignment.find('=') + 1));
    std::vector<std::string> typed = inertial(c.switches);
    typed.push_back(c.assignment);
    const Refusal read = refusal(typed);
    const Scene scene = scene_with(inertial(c.switches));
    SimSettings built = scene.sim;
    c.set(*built.elastic(), value);
    expect_the_same_refusal(built, scene, key, read);
  }
}

// The same for the linear contact's two keys.
TEST(ForceSections, TheLinearContactsRangeIsTheSameForTheReaderAndTheChecks) {
  for (const auto& [assignment, damping] : {std::pair{"contact.stiffness=1e3", false}, {"contact.damping=-1", true}}) {
    const std::string typed = assignment;
    const Refusal read = refusal(inertial({"contact.law=linear", typed}));
    const Scene scene = scene_with(inertial({"contact.law=linear"}));
    SimSettings built = scene.sim;
    LinearContactSettings& spring = *built.linear_contact();
    (damping ? spring.damping_N_s_per_m : spring.stiffness_N_per_m) = std::stod(typed.substr(typed.find('=') + 1));
    expect_the_same_refusal(built, scene, typed.substr(0, typed.find('=')), read);
  }
}

// The tables of sim/force_setting_ranges.h drive both the reading and the
// refusal: every key of every section is taken under each model its table
// names and refused, naming the key, under every other.
TEST(ForceSections, EveryKeyIsTakenByItsModelsAndRefusedByTheOthers) {
  LinearContactSettings linear;
  std::optional<double> damping;
  HertzContactSettings hertz;
  LumpedTrackSettings lumped;
  DiscreteTrackSettings discrete;
  PrimarySuspensionSettings sprung;
  BogieSettings bogie;
  struct Section {
    std::string name, switch_key;
    std::vector<std::string> values;
    std::vector<ForceSettingKey> keys;
    std::vector<std::string> others;  // what the other sections need for each value
  };
  const std::vector<Section> sections = {
      {"contact", "law", {"rigid", "linear", "hertz"}, contact_keys(linear, damping, hertz), {}},
      {"track", "model", {"rigid", "lumped", "discrete"}, track_keys(lumped, discrete, discrete.support),
       {"contact.law=hertz"}},
      {"vehicle", "model", {"load", "sprung", "bogie"}, vehicle_keys(sprung, bogie, true),
       {"contact.law=hertz", "track.model=discrete"}}};
  int checked = 0;
  for (const Section& section : sections) {
    for (const ForceSettingKey& k : section.keys) {
      // Its default, or where it has none the end of its range.
      double* const* field = std::get_if<double*>(&k.field);
      int* const* count = std::get_if<int*>(&k.field);
      const double value = field ? **field : count ? **count : k.range.lo_open ? k.range.hi : k.range.lo;
      const std::string typed = section.name + "." + k.key + "=" + setting_number(value);
      for (std::size_t model = 1; model < section.values.size(); ++model) {
        std::vector<std::string> overrides = inertial(section.others);
        if (section.name == "contact" && model == 1) overrides = kInertial;  // the linear law alone
        overrides.push_back(section.name + "." + section.switch_key + "=" + section.values[model]);
        overrides.push_back(typed);
        const Refusal r = refusal(overrides);
        ++checked;
        if ((k.models & (1u << model)) != 0) {
          EXPECT_EQ(r.key, "") << typed << " under " << section.values[model] << ": " << r.what;
        } else {
          EXPECT_EQ(r.key, section.name + "." + k.key) << typed << " under " << section.values[model];
          EXPECT_TRUE(contains(r.message, "only applies with " + section.name + "." + section.switch_key)) << r.what;
        }
      }
    }
  }
  std::printf("%d (key, model) pairs checked\n", checked);
  EXPECT_EQ(checked, 2 * (4 + 11 + 9));
}

// The [sim] key table (sim/setting_ranges.h) drives the reading and both
// refusals: every key, typed at its default (near the open end of its range
// where it has none), is taken by the runs the table names and refused,
// naming the key, by the others: the kinematic run, the inertial run Bullet
// steps (here on a rigid contact) and the force run.
TEST(ForceSections, EverySimKeyIsTakenByItsRunsAndRefusedByTheOthers) {
  SimSettings kinematic;
  SimSettings inertial_mode;
  inertial_mode.make_inertial();
  const std::vector<SimSettingKey> kinematic_keys = sim_keys(kinematic);
  const std::vector<SimSettingKey> inertial_keys = sim_keys(inertial_mode);
  const std::vector<std::pair<unsigned, std::vector<std::string>>> runs = {
      {kKinematicRun, {}}, {kBulletInertialRun, kInertial}, {kForceRun, inertial({"contact.law=hertz"})}};
  int checked = 0;
  for (std::size_t i = 0; i < kinematic_keys.size(); ++i) {
    const SimSettingKey& k = kinematic_keys[i];
    // The field of the mode that has it (the preload the kinematic one's, the load the inertial one's).
    const SimKeyField& field =
        std::holds_alternative<std::monostate>(k.field) ? inertial_keys[i].field : k.field;
    std::string value;
    if (double* const* number = std::get_if<double*>(&field)) value = setting_number(**number);
    if (std::get_if<std::optional<double>*>(&field)) {
      value = setting_number(k.range.lo_open ? k.range.lo + 1e-3 * (k.range.hi - k.range.lo) : k.range.lo);
    }
    if (int* const* count = std::get_if<int*>(&field)) value = std::to_string(**count);
    if (bool* const* flag = std::get_if<bool*>(&field)) value = **flag ? "true" : "false";
    if (NarrowPhase* const* phase = std::get_if<NarrowPhase*>(&field)) value = to_string(**phase);
    if (HorizontalMotion* const* motion = std::get_if<HorizontalMotion*>(&field)) value = to_string(**motion);
    if (value.empty()) continue;  // the mode, which picks the run
    const std::string key = std::string("sim.") + k.key;
    for (const auto& [run, switches] : runs) {
      std::vector<std::string> overrides = switches;
      // What the Bullet run needs for the key to change something (the run refuses it otherwise).
      if (run == kBulletInertialRun && key == "sim.carrier_mass") overrides.push_back("sim.horizontal=free");
      if (run == kBulletInertialRun && key == "sim.radius_of_gyration") overrides.push_back("sim.friction=0.3");
      overrides.push_back(key + "=" + value);
      const Refusal r = refusal(overrides);
      ++checked;
      if ((k.runs & run) != 0) {
        EXPECT_EQ(r.key, "") << key << "=" << value << " in run " << run << ": " << r.what;
      } else {
        EXPECT_EQ(r.key, key) << key << "=" << value << " in run " << run << ": " << r.what;
      }
    }
  }
  std::printf("%d (key, run) pairs checked\n", checked);
  // The 25 keys `simulate --help` lists besides the mode, in three runs.
  EXPECT_EQ(checked, 3 * 25);
}

// Each [sim] key's range is written once (sim/setting_ranges.h): a value out
// of it is refused alike typed in a scene or built in code (by
// check_sim_settings), with the same key and the same range. The values are
// outside anything a run could use (a 1 s step, a 1 m margin, a negative
// load), so the test does not restate a bound.
TEST(ForceSections, ASimKeysRangeIsTheSameForTheReaderAndTheChecks) {
  const std::vector<std::string> kinematic_run;
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {kinematic_run, "sim.time_step=1"},
      {kinematic_run, "sim.refined_time_step=1"},
      {kinematic_run, "sim.refine_distance=1"},
      {kinematic_run, "sim.refine_hold=5"},
      {kinematic_run, "sim.margin=1"},
      {kinematic_run, "sim.contact_breaking_threshold=1"},
      {kinematic_run, "sim.contact_processing_threshold=1"},
      {kinematic_run, "sim.split_impulse_threshold=1"},
      {kinematic_run, "sim.slop=1"},
      {kinematic_run, "sim.preload=-1"},
      {kinematic_run, "sim.friction=5"},
      {kinematic_run, "sim.restitution=2"},
      {kinematic_run, "sim.disc_half_width=1"},
      {kinematic_run, "sim.approach_distance=1000"},
      {kinematic_run, "sim.run_out_time=100"},
      {kInertial, "sim.wheel_load=-1"},
      {inertial({"sim.horizontal=free"}), "sim.carrier_mass=-1"},
      {inertial({"sim.friction=0.3"}), "sim.radius_of_gyration=100"},
      {kInertial, "sim.flat_approach=1000"},
      {kInertial, "sim.force_time_step=1"},
  };
  for (const auto& [switches, assignment] : cases) {
    const std::string key = assignment.substr(0, assignment.find('='));
    const double value = std::stod(assignment.substr(assignment.find('=') + 1));
    std::vector<std::string> typed = switches;
    typed.push_back(assignment);
    const Refusal read = refusal(typed);
    const Scene scene = scene_with(switches);
    SimSettings built = scene.sim;
    for (const SimSettingKey& k : sim_keys(built)) {
      if (key != std::string("sim.") + k.key) continue;
      if (double* const* number = std::get_if<double*>(&k.field)) **number = value;
      if (std::optional<double>* const* optional = std::get_if<std::optional<double>*>(&k.field)) **optional = value;
    }
    expect_the_same_refusal(built, scene, key, read);
  }
}

// track.nodes_per_bay, the discrete track's grid (a numerical choice the user
// may refine): even, so a sleeper sits on a bay's middle node and the joint
// on a bay's end; 4 to 64 (force_setting_ranges.h); and no finer than the
// step can hold. The rail's stiffest mode rings at 4 / h^2 sqrt(EI / mu)
// (Euler): h = 0.6 m / 16 = 0.0375 m gives 4 / 1.40625e-3 x sqrt(6.38e6 /
// 60.2) = 9.26e5 rad/s, so the default step (4e-6 s) holds at most
// 1 / 4e-6 s = 2.5e5 rad/s: h >= sqrt(4 x 4e-6 x 325.55) = 0.0722 m, 8 nodes
// a bay (0.075 m); 16 need a step <= 1 / 9.26e5 = 1.07992e-6 s. Each refusal names the key.
TEST(ForceSections, NodesPerBayIsEvenInItsRangeAndNoFinerThanTheStepHolds) {
  const std::vector<std::string> discrete = inertial({"contact.law=hertz", "track.model=discrete"});
  const auto with = [&](std::vector<std::string> more) {
    more.insert(more.begin(), discrete.begin(), discrete.end());
    return more;
  };
  // The grid against the step is checked where a run is built (SceneCheck::simulation), as simulate does.
  const auto refusal = [](const std::vector<std::string>& overrides) -> Refusal {
    try {
      parse_scene(kScene, "test.toml", overrides, SceneCheck::simulation);
    } catch (const InputError& error) {
      std::printf("%s\n", error.what());
      return {error.key(), error.message(), error.what()};
    }
    std::printf("(accepted)\n");
    return {};
  };
  EXPECT_EQ(scene_with(discrete).sim.elastic()->discrete_track->nodes_per_bay, 8);  // the default, unchanged
  for (const std::string bad : {"7", "2", "66", "8.5"}) {
    const Refusal r = refusal(with({"track.nodes_per_bay=" + bad}));
    EXPECT_EQ(r.key, "track.nodes_per_bay") << bad;
    EXPECT_TRUE(contains(r.message, bad == "7" ? "must be even" : "[4, 64]")) << r.what;
  }
  // A finer grid than the default step holds, typed after it: the grid is blamed, with the finest that fits.
  const Refusal fine = refusal(with({"track.nodes_per_bay=16"}));
  EXPECT_EQ(fine.key, "track.nodes_per_bay");
  EXPECT_TRUE(contains(fine.message, "must be <= 8 for sim.force_time_step = 4e-06 s")) << fine.what;
  EXPECT_TRUE(contains(fine.message, "1 / omega = 1.07992e-06 s")) << fine.what;
  // Both typed alike (two --set): the step takes the blame, with its bound; one short enough runs.
  const Refusal step = refusal(with({"track.nodes_per_bay=16", "sim.force_time_step=2e-6"}));
  EXPECT_EQ(step.key, "sim.force_time_step");
  EXPECT_TRUE(contains(step.message, "h = track.sleeper_spacing / 16")) << step.what;
  EXPECT_EQ(refusal(with({"track.nodes_per_bay=16", "sim.force_time_step=1e-6"})).key, "");
  EXPECT_EQ(scene_with(with({"track.nodes_per_bay=16", "sim.force_time_step=1e-6"}))
                .sim.elastic()->discrete_track->nodes_per_bay,
            16);
  // Built in code, an odd grid is refused by the same key.
  Scene scene = scene_with(with({}));
  SimSettings built = scene.sim;
  built.elastic()->discrete_track->nodes_per_bay = 9;
  try {
    check_sim_settings(built, scene.joint, scene.wheel);
    ADD_FAILURE() << "an odd grid built in code was accepted";
  } catch (const InputError& error) {
    std::printf("built in code: %s\n", error.what());
    EXPECT_EQ(error.key(), "track.nodes_per_bay");
  }
}

}  // namespace
}  // namespace railjoint
