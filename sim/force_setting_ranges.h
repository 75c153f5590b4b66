#pragma once
// The range of each [contact], [track] and [vehicle] setting of a force run
// (elastic_track_settings.h, bogie_settings.h), written once: the scene
// reader refuses a typed value outside it, naming the key
// (scenes/force_sections.cpp), and check_inertial_settings refuses one
// built in code (setting_checks.h). setting_ranges.h holds the [sim] keys'.
// Plain header: no Bullet.

#include "sim/setting_ranges.h"

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

}  // namespace railjoint
