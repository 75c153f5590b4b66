#pragma once
// The range of each [contact], [track] and [vehicle] setting of a force run
// (elastic_track_settings.h, bogie_settings.h), and the tables that tie each
// key to its model, its range and its field, written once: the scene reader
// reads a model's keys and refuses another model's by them
// (scenes/force_sections.cpp), and check_inertial_settings refuses a value
// built in code outside its range (setting_checks.h). setting_ranges.h holds
// the [sim] keys'. Plain header: no Bullet.

#include <optional>
#include <variant>
#include <vector>

#include "sim/elastic_track_settings.h"
#include "sim/setting_ranges.h"
#include "sim/sim_settings.h"

namespace railjoint {

namespace contact_range {

// The steels of wheel and rail, for every law (and the local model's patch).
inline constexpr SettingRange youngs_modulus{1e6, 1e13, false, false, "Pa"};
inline constexpr SettingRange poisson_ratio{0.0, 0.5, false, true, ""};
// law = "linear". 1e6 N/m already lets the static wheel load sink the wheel
// by ~0.1 m; 1e12 N/m is stiffer than any wheel-rail contact. 1e8 N s/m is
// ~50x critical damping at the Hertzian stiffness and the thesis's wheel mass.
inline constexpr SettingRange stiffness{1e6, 1e12, false, false, "N/m"};
inline constexpr SettingRange damping{0.0, 1e8, false, false, "N s/m"};
// law = "hertz". Physical constants lie near 4e-8 m/N^(2/3); the range takes
// a contact a thousand times stiffer or softer.
inline constexpr SettingRange hertz_constant{1e-11, 1e-5, false, false, "m/N^(2/3)"};
inline constexpr SettingRange restitution{0.0, 1.0, false, false, ""};

}  // namespace contact_range

namespace track_range {

// The supports of both elastic tracks: stiffnesses from a soft subgrade to
// a slab, masses from a few kg to a whole span's sleepers. The stiffnesses,
// the bending stiffness and the sleeper spacing also set a discrete track's
// work (check_sim_run_length's budget).
inline constexpr SettingRange support_stiffness{1e5, 1e11, false, false, "N/m"};
inline constexpr SettingRange support_damping{0.0, 1e8, false, false, "N s/m"};
inline constexpr SettingRange sleeper_mass{1.0, 1e4, false, false, "kg"};
// model = "lumped".
inline constexpr SettingRange rail_mass{1.0, 1e4, false, false, "kg"};
// model = "discrete": from a light rail (1e5 N m^2) to a girder; 0.2-2 m
// between sleepers.
inline constexpr SettingRange bending_stiffness{1e5, 1e9, false, false, "N m^2"};
inline constexpr SettingRange mass_per_length{5.0, 1e4, false, false, "kg/m"};
inline constexpr SettingRange sleeper_spacing{0.2, 2.0, false, false, "m"};
inline constexpr SettingRange joint_bending_stiffness{0.0, 1e10, false, false, "N m/rad"};
// The rail's grid, a numerical choice (docs/forces.md, "The rail's grid"):
// even, so a sleeper sits on a bay's middle node and the joint on a bay's
// end. 4 still puts a node between the joint and each sleeper; 64 needs a
// step of 6.7e-8 s on 60E1 (the step falls as 1 / nodes^2) and 512 times
// the default grid's work.
inline constexpr SettingRange nodes_per_bay{4.0, 64.0, false, false, ""};
// beam = "timoshenko": steels and alloys (G 1-1e3 GPa); kappa in (0, 1]
// (5/6 for a rectangle, about 0.4 for a rail); a tram rail's section to a
// girder's; rho I from a light rail's (~0.05 kg m) to a girder's. A small
// rotary inertia stiffens the chain's fastest mode: check_inertial_settings
// holds the step below it.
inline constexpr SettingRange shear_modulus{1e9, 1e12, false, false, "Pa"};
inline constexpr SettingRange shear_coefficient{0.0, 1.0, true, false, ""};
inline constexpr SettingRange section_area{1e-4, 1.0, false, false, "m^2"};
inline constexpr SettingRange rotary_inertia{1e-3, 1e3, false, false, "kg m"};

}  // namespace track_range

namespace vehicle_range {

// model = "sprung" and "bogie": the primary suspension.
inline constexpr SettingRange primary_stiffness{1e3, 1e10, false, false, "N/m"};
inline constexpr SettingRange primary_damping{0.0, 1e8, false, false, "N s/m"};
inline constexpr SettingRange sprung_mass{1.0, 1e6, false, false, "kg"};
// model = "bogie": masses from a light frame to a heavy car's share, a
// wheelbase from a short freight bogie's to a two-axle wagon's.
inline constexpr SettingRange axle_spacing{1.0, 20.0, false, false, "m"};
inline constexpr SettingRange frame_mass{10.0, 1e5, false, false, "kg"};
inline constexpr SettingRange frame_pitch_inertia{1.0, 1e6, false, false, "kg m^2"};
inline constexpr SettingRange body_mass{1.0, 1e6, false, false, "kg"};
inline constexpr SettingRange secondary_stiffness{0.0, 1e10, false, false, "N/m"};
inline constexpr SettingRange secondary_damping{0.0, 1e8, false, false, "N s/m"};

}  // namespace vehicle_range

/// The values of the section's switch a key applies to, a bit each in the
/// order of the switch's choices: contact.law = "rigid", "linear", "hertz";
/// track.model = "rigid", "lumped", "discrete"; vehicle.model = "load",
/// "sprung", "bogie".
inline constexpr unsigned kLinearLaw = 2, kHertzLaw = 4;
inline constexpr unsigned kLumpedTrack = 2, kDiscreteTrack = 4, kElasticTrack = kLumpedTrack | kDiscreteTrack;
inline constexpr unsigned kSprungVehicle = 2, kBogieVehicle = 4;
/// track.beam = "euler", "timoshenko" (with track.model = "discrete").
inline constexpr unsigned kTimoshenkoBeam = 2;

/// One key of a switched section, in the order the reader reads them: the
/// models that take it, its range and the setting it fills (a number with a
/// default, or one that may be left out).
struct ForceSettingKey {
  const char* key;  ///< within its section: "pad_stiffness"
  unsigned models;
  SettingRange range;
  std::variant<double*, std::optional<double>*, int*> field;  ///< int: a count (read as an integer)
};

/// [contact]'s keys besides the law and the steels (which every law takes).
inline std::vector<ForceSettingKey> contact_keys(LinearContactSettings& linear, std::optional<double>& linear_damping,
                                                 HertzContactSettings& hertz) {
  return {{"stiffness", kLinearLaw, contact_range::stiffness, &linear.stiffness_N_per_m},
          {"damping", kLinearLaw, contact_range::damping, &linear_damping},
          {"hertz_constant", kHertzLaw, contact_range::hertz_constant, &hertz.hertz_constant_m_per_N2_3},
          {"restitution", kHertzLaw, contact_range::restitution, &hertz.restitution}};
}

/// [track]'s; the support's keys fill `support`, the lumped or the discrete track's.
inline std::vector<ForceSettingKey> track_keys(LumpedTrackSettings& lumped, DiscreteTrackSettings& discrete,
                                               TrackSupportSettings& support) {
  return {{"rail_mass", kLumpedTrack, track_range::rail_mass, &lumped.rail_mass_kg},
          {"bending_stiffness", kDiscreteTrack, track_range::bending_stiffness, &discrete.bending_stiffness_N_m2},
          {"mass_per_length", kDiscreteTrack, track_range::mass_per_length, &discrete.mass_per_length_kg_per_m},
          {"sleeper_spacing", kDiscreteTrack, track_range::sleeper_spacing, &discrete.sleeper_spacing_m},
          {"pad_stiffness", kElasticTrack, track_range::support_stiffness, &support.pad_stiffness_N_per_m},
          {"pad_damping", kElasticTrack, track_range::support_damping, &support.pad_damping_N_s_per_m},
          {"sleeper_mass", kElasticTrack, track_range::sleeper_mass, &support.sleeper_mass_kg},
          {"ballast_stiffness", kElasticTrack, track_range::support_stiffness, &support.ballast_stiffness_N_per_m},
          {"ballast_damping", kElasticTrack, track_range::support_damping, &support.ballast_damping_N_s_per_m},
          {"joint_bending_stiffness", kDiscreteTrack, track_range::joint_bending_stiffness,
           &discrete.joint_bending_stiffness_N_m_per_rad},
          {"nodes_per_bay", kDiscreteTrack, track_range::nodes_per_bay, &discrete.nodes_per_bay}};
}

/// [track]'s keys of a Timoshenko rail (track.beam = "timoshenko").
inline std::vector<ForceSettingKey> timoshenko_keys(TimoshenkoRailSettings& rail) {
  return {{"shear_modulus", kTimoshenkoBeam, track_range::shear_modulus, &rail.shear_modulus_Pa},
          {"shear_coefficient", kTimoshenkoBeam, track_range::shear_coefficient, &rail.shear_coefficient},
          {"section_area", kTimoshenkoBeam, track_range::section_area, &rail.section_area_m2},
          {"rotary_inertia", kTimoshenkoBeam, track_range::rotary_inertia, &rail.rotary_inertia_kg_m}};
}

/// [vehicle]'s; the primary suspension's keys fill the bogie's when `bogie_primary`, else the sprung mass's.
inline std::vector<ForceSettingKey> vehicle_keys(PrimarySuspensionSettings& sprung, BogieSettings& bogie,
                                                 bool bogie_primary) {
  const unsigned primary = kSprungVehicle | kBogieVehicle;
  return {{"sprung_mass", kSprungVehicle, vehicle_range::sprung_mass, &sprung.sprung_mass_kg},
          {"axle_spacing", kBogieVehicle, vehicle_range::axle_spacing, &bogie.axle_spacing_m},
          {"frame_mass", kBogieVehicle, vehicle_range::frame_mass, &bogie.frame_mass_kg},
          {"frame_pitch_inertia", kBogieVehicle, vehicle_range::frame_pitch_inertia, &bogie.frame_pitch_inertia_kg_m2},
          {"body_mass", kBogieVehicle, vehicle_range::body_mass, &bogie.body_mass_kg},
          {"primary_stiffness", primary, vehicle_range::primary_stiffness,
           bogie_primary ? &bogie.primary_stiffness_N_per_m : &sprung.primary_stiffness_N_per_m},
          {"primary_damping", primary, vehicle_range::primary_damping,
           bogie_primary ? &bogie.primary_damping_N_s_per_m : &sprung.primary_damping_N_s_per_m},
          {"secondary_stiffness", kBogieVehicle, vehicle_range::secondary_stiffness, &bogie.secondary_stiffness_N_per_m},
          {"secondary_damping", kBogieVehicle, vehicle_range::secondary_damping, &bogie.secondary_damping_N_s_per_m}};
}

}  // namespace railjoint
