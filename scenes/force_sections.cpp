#include "scenes/force_sections.h"

#include <functional>
#include <optional>
#include <set>
#include <string>

#include "models/input_error.h"
#include "scenes/switched_keys.h"
#include "sim/force_setting_ranges.h"

namespace railjoint {

namespace {

// The [sim] keys a force run reads: its mode, load and step, where it
// starts and ends, the thin disc's stand-in width and the contact's reach.
// Every other key [sim] takes is the rigid runs' (Bullet's steps, solver
// and contact) and is refused, so a key added to [sim] is refused in a
// force run until the run reads it.
const std::set<std::string, std::less<>> kForceRunSimKeys = {
    "mode", "wheel_load", "force_time_step", "approach_distance", "run_out_time", "disc_half_width",
    "contact_breaking_threshold"};
// Of the others, the rigid contact's horizontal motion and dissipation.
const std::vector<std::string> kRigidContactSimKeys = {"friction", "restitution", "horizontal", "carrier_mass",
                                                       "radius_of_gyration"};

const std::vector<std::string> kLinearKeys = {"stiffness", "damping"};
const std::vector<std::string> kHertzKeys = {"hertz_constant", "restitution"};
// Keys of the support (pad, sleeper, ballast) that both elastic tracks have.
const std::vector<std::string> kSupportKeys = {"pad_stiffness", "pad_damping", "sleeper_mass", "ballast_stiffness",
                                               "ballast_damping"};
const std::vector<std::string> kLumpedOnlyKeys = {"rail_mass"};
const std::vector<std::string> kDiscreteOnlyKeys = {"bending_stiffness", "mass_per_length", "sleeper_spacing",
                                                    "joint_bending_stiffness"};

// The support's keys, with the ranges both tracks take (every range:
// sim/force_setting_ranges.h).
TrackSupportSettings read_support(SectionReader& in) {
  TrackSupportSettings s;
  s.pad_stiffness_N_per_m =
      in.number("pad_stiffness", s.pad_stiffness_N_per_m, Range::of(track_range::support_stiffness));
  s.pad_damping_N_s_per_m = in.number("pad_damping", s.pad_damping_N_s_per_m, Range::of(track_range::support_damping));
  s.sleeper_mass_kg = in.number("sleeper_mass", s.sleeper_mass_kg, Range::of(track_range::sleeper_mass));
  s.ballast_stiffness_N_per_m = in.number("ballast_stiffness", s.ballast_stiffness_N_per_m,
                                          Range::of(track_range::support_stiffness));
  s.ballast_damping_N_s_per_m = in.number("ballast_damping", s.ballast_damping_N_s_per_m, Range::of(track_range::support_damping));
  return s;
}
const std::vector<std::string> kSprungOnlyKeys = {"sprung_mass"};
const std::vector<std::string> kPrimaryKeys = {"primary_stiffness", "primary_damping"};
const std::vector<std::string> kBogieOnlyKeys = {"axle_spacing",        "frame_mass",          "frame_pitch_inertia",
                                                 "body_mass",           "secondary_stiffness", "secondary_damping"};

// [vehicle] model = "bogie" (sim/bogie_settings.h).
BogieSettings read_bogie(SectionReader& vehicle, double wheel_load_N) {
  BogieSettings b;
  b.axle_spacing_m = vehicle.number("axle_spacing", b.axle_spacing_m, Range::of(vehicle_range::axle_spacing));
  b.frame_mass_kg = vehicle.number("frame_mass", b.frame_mass_kg, Range::of(vehicle_range::frame_mass));
  b.frame_pitch_inertia_kg_m2 =
      vehicle.number("frame_pitch_inertia", b.frame_pitch_inertia_kg_m2, Range::of(vehicle_range::frame_pitch_inertia));
  b.body_mass_kg = vehicle.optional_number("body_mass", Range::of(vehicle_range::body_mass));
  if (!(bogie_body_mass_kg(b, wheel_load_N, kStandardGravity_m_per_s2) >= 1.0)) {
    throw InputError(vehicle.file(), vehicle.qualified("model"),
                     "needs vehicle.body_mass [kg] (1 to 1e6) when 2 sim.wheel_load / g does not exceed "
                     "vehicle.frame_mass by 1 kg (the body's share defaults to the rest of the two wheels' loads)");
  }
  b.primary_stiffness_N_per_m = vehicle.number("primary_stiffness", b.primary_stiffness_N_per_m, Range::of(vehicle_range::primary_stiffness));
  b.primary_damping_N_s_per_m = vehicle.number("primary_damping", b.primary_damping_N_s_per_m, Range::of(vehicle_range::primary_damping));
  b.secondary_stiffness_N_per_m =
      vehicle.number("secondary_stiffness", b.secondary_stiffness_N_per_m, Range::of(vehicle_range::secondary_stiffness));
  b.secondary_damping_N_s_per_m =
      vehicle.number("secondary_damping", b.secondary_damping_N_s_per_m, Range::of(vehicle_range::secondary_damping));
  return b;
}

}  // namespace

HertzMaterial read_force_sections(SectionReader& contact, SectionReader& track, SectionReader& vehicle,
                                  SectionReader& sim_keys, SimSettings& sim, const KeyOrigins& origins) {
  const std::string law = contact.choice("law", "rigid", {"rigid", "linear", "hertz"});
  // The steels, one pair for the whole program (Hertz's elliptical constant
  // of a force run, the local model's Hertz patch), whatever the law.
  HertzMaterial material;
  material.youngs_modulus_Pa = contact.number("youngs_modulus", material.youngs_modulus_Pa, Range::of(contact_range::youngs_modulus));
  material.poisson_ratio = contact.number("poisson_ratio", material.poisson_ratio, Range::of(contact_range::poisson_ratio));
  const std::string track_model = track.choice("model", "rigid", {"rigid", "lumped", "discrete"});
  const std::string vehicle_model = vehicle.choice("model", "load", {"load", "sprung", "bogie"});
  if (sim.mode() == SimMode::kinematic) {
    const char* const why = "only applies to sim.mode = \"inertial\" (the kinematic mode presses a rigid wheel "
                            "onto a rigid rail and measures the jump at the impact: no contact force, no track)";
    // A --set sim.mode=kinematic on a force scene is the mode's fault.
    const auto refuse = [&](const SectionReader& in, const std::string& key, const std::string& value) {
      if (origins("sim.mode") > origins(in.qualified(key))) {
        throw InputError(sim_keys.file(), "sim.mode",
                         "must be \"inertial\" with " + in.qualified(key) + " = \"" + value + "\" (" +
                             origin_text(origins(in.qualified(key))) + "): the kinematic mode presses a rigid wheel "
                             "onto a rigid rail (no contact force, no track); leave sim.mode as the file has it");
      }
      throw InputError(in.file(), in.qualified(key), why);
    };
    if (law != "rigid") refuse(contact, "law", law);
    if (track_model != "rigid") refuse(track, "model", track_model);
    if (vehicle_model != "load") refuse(vehicle, "model", vehicle_model);
  }
  // Every key a section holds besides its switch only applies with that
  // switch set (switched_keys.h).
  refuse_keys_unless(contact, origins, law == "linear", kLinearKeys, "law",
                     "only applies with contact.law = \"linear\"");
  refuse_keys_unless(contact, origins, law == "hertz", kHertzKeys, "law", "only applies with contact.law = \"hertz\"");
  refuse_keys_unless(track, origins, track_model != "rigid", kSupportKeys, "model",
                     "only applies with track.model = \"lumped\" or \"discrete\"");
  refuse_keys_unless(track, origins, track_model == "lumped", kLumpedOnlyKeys, "model",
                     "only applies with track.model = \"lumped\"");
  refuse_keys_unless(track, origins, track_model == "discrete", kDiscreteOnlyKeys, "model",
                     "only applies with track.model = \"discrete\"");
  refuse_keys_unless(vehicle, origins, vehicle_model == "sprung", kSprungOnlyKeys, "model",
                     "only applies with vehicle.model = \"sprung\"");
  refuse_keys_unless(vehicle, origins, vehicle_model == "sprung" || vehicle_model == "bogie", kPrimaryKeys, "model",
                     "only applies with vehicle.model = \"sprung\" or \"bogie\"");
  refuse_keys_unless(vehicle, origins, vehicle_model == "bogie", kBogieOnlyKeys, "model",
                     "only applies with vehicle.model = \"bogie\"");
  // The bogie's wheels stand axle_spacing apart on one rail that rings
  // between them: the lumped track's one rail mass would put both on the
  // same spot, and a rigid track has nothing to pass from one to the other.
  if (vehicle_model == "bogie" && law == "hertz" && track_model != "discrete") {
    // A --set track.model on a bogie scene is the track's fault.
    if (origins(track.qualified("model")) > origins(vehicle.qualified("model"))) {
      throw InputError(track.file(), track.qualified("model"),
                       "must be \"discrete\" with vehicle.model = \"bogie\" (got \"" + track_model +
                           "\"): the lumped track has one rail mass under both wheels, a rigid one no ringing to "
                           "pass from one to the other");
    }
    throw InputError(vehicle.file(), vehicle.qualified("model"),
                     "\"bogie\" needs track.model = \"discrete\" (got \"" + track_model +
                         "\"): its two wheels stand axle_spacing apart on a rail that carries the first one's "
                         "ringing to the second; the lumped track has one rail mass under both, a rigid one none");
  }
  if (law != "hertz") {
    const char* const why = "needs contact.law = \"hertz\" (forces on an elastic track and under a suspension follow "
                            "Hertz's contact law)";
    if (track_model != "rigid") throw InputError(track.file(), track.qualified("model"), why);
    if (vehicle_model != "load") throw InputError(vehicle.file(), vehicle.qualified("model"), why);
    if (sim_keys.has("force_time_step")) {
      throw InputError(sim_keys.file(), sim_keys.qualified("force_time_step"), "only applies with contact.law = \"hertz\"");
    }
  }

  // Past the check above, a contact law other than "rigid" is an inertial run's.
  if (law == "linear") {
    LinearContactSettings& spring = sim.inertial()->contact.emplace<LinearContactSettings>();
    // The default is the textbook linearised Hertz stiffness at 100 kN.
    spring.stiffness_N_per_m = contact.number("stiffness", 1.4e9, Range::of(contact_range::stiffness));
    // Left out, it is critical for the scene's wheel (read_scene sets it: the wheel is read there).
    if (const std::optional<double> damping = contact.optional_number("damping", Range::of(contact_range::damping))) {
      spring.damping_N_s_per_m = *damping;
    }
  }
  if (law == "hertz") {
    ElasticCrossingSettings& elastic = sim.inertial()->contact.emplace<ElasticCrossingSettings>();
    elastic.contact.hertz_constant_m_per_N2_3 =
        contact.optional_number("hertz_constant", Range::of(contact_range::hertz_constant));
    elastic.contact.restitution = contact.number("restitution", 1.0, Range::of(contact_range::restitution));
    elastic.contact.youngs_modulus_Pa = material.youngs_modulus_Pa;
    elastic.contact.poisson_ratio = material.poisson_ratio;
    // The force run holds the horizontal speed on a frictionless contact
    // and steps at its own fixed step with the exact narrow phase: the
    // rigid-contact switches that would change nothing are refused.
    for (const std::string& key : kRigidContactSimKeys) {
      if (sim_keys.has(key)) {
        throw InputError(sim_keys.file(), sim_keys.qualified(key),
                         std::string("does not apply with contact.law = \"hertz\" (the force run holds the horizontal "
                                     "speed on a frictionless contact") +
                             (key == "restitution" ? "; its dissipation is contact.restitution)" : ")"));
      }
    }
    for (const std::string& key : sim_keys.given_keys()) {
      if (kForceRunSimKeys.contains(key) || key == "flat_approach") continue;
      throw InputError(sim_keys.file(), sim_keys.qualified(key),
                       "does not apply with contact.law = \"hertz\": the force run steps at sim.force_time_step "
                       "with the exact narrow phase and applies Hertz's force itself (Bullet solves no contact)");
    }
    // Its start is the static state on the incoming slope; the flat
    // approach's entry kink throws the wheel before the joint.
    if (sim_keys.has("flat_approach")) {
      throw InputError(sim_keys.file(), sim_keys.qualified("flat_approach"),
                       "does not apply with contact.law = \"hertz\" (a force run starts in its static state on the "
                       "incoming slope, sim.approach_distance before the joint)");
    }
    if (track_model == "lumped") {
      LumpedTrackSettings& t = elastic.track.emplace();
      t.rail_mass_kg = track.number("rail_mass", t.rail_mass_kg, Range::of(track_range::rail_mass));
      t.support = read_support(track);
    }
    if (track_model == "discrete") {
      DiscreteTrackSettings& t = elastic.discrete_track.emplace();
      t.bending_stiffness_N_m2 =
          track.number("bending_stiffness", t.bending_stiffness_N_m2, Range::of(track_range::bending_stiffness));
      t.mass_per_length_kg_per_m = track.number("mass_per_length", t.mass_per_length_kg_per_m, Range::of(track_range::mass_per_length));
      t.sleeper_spacing_m =
          track.number("sleeper_spacing", t.sleeper_spacing_m, Range::of(track_range::sleeper_spacing));
      t.support = read_support(track);
      t.joint_bending_stiffness_N_m_per_rad =
          track.optional_number("joint_bending_stiffness", Range::of(track_range::joint_bending_stiffness));
    }
    if (vehicle_model == "sprung") {
      PrimarySuspensionSettings& s = elastic.vehicle.emplace();
      s.sprung_mass_kg = vehicle.optional_number("sprung_mass", Range::of(vehicle_range::sprung_mass));
      if (!s.sprung_mass_kg && !(sim.inertial()->wheel_load_N > 0.0)) {
        throw InputError(vehicle.file(), vehicle.qualified("model"),
                         "needs vehicle.sprung_mass [kg] when sim.wheel_load is 0 (the sprung mass defaults to "
                         "wheel_load / g)");
      }
      s.primary_stiffness_N_per_m = vehicle.number("primary_stiffness", s.primary_stiffness_N_per_m, Range::of(vehicle_range::primary_stiffness));
      s.primary_damping_N_s_per_m = vehicle.number("primary_damping", s.primary_damping_N_s_per_m, Range::of(vehicle_range::primary_damping));
    }
    if (vehicle_model == "bogie") elastic.bogie = read_bogie(vehicle, sim.inertial()->wheel_load_N);
  }
  contact.finish();
  track.finish();
  vehicle.finish();
  return material;
}

}  // namespace railjoint
