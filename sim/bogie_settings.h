#pragma once
// A bogie above the force run's wheel line ([vehicle] model = "bogie"):
// two wheelsets axle_spacing apart on the same rail, under a bogie frame
// (bounce and pitch) on a primary suspension at each wheel, and a car body
// share on the secondary suspension at the frame's centre. The force run
// follows one rail (the wheel is a wheel, sim.wheel_load its static load):
// every mass and stiffness here is the share on that rail, half the
// bogie's. The defaults are assumed, typical of a passenger bogie (a 2.6 t
// frame of 1.5 t m^2 pitch inertia, 1 MN/m and 10 kN s/m per axle box as
// the sprung model's primary, an air spring of 0.5 MN/m and 20 kN s/m),
// not taken from one published vehicle.

#include <optional>

namespace railjoint {

struct BogieSettings {
  double axle_spacing_m = 2.5;  ///< issue 41's default (a typical passenger bogie's wheelbase)
  double frame_mass_kg = 1300.0;
  double frame_pitch_inertia_kg_m2 = 750.0;
  /// Empty: 2 wheel_load / g less the frame, so the weights above the two
  /// wheels are the static loads they carry.
  std::optional<double> body_mass_kg;
  double primary_stiffness_N_per_m = 1e6;  ///< per wheel
  double primary_damping_N_s_per_m = 10e3;
  double secondary_stiffness_N_per_m = 0.5e6;
  double secondary_damping_N_s_per_m = 20e3;
};

/// The car body share's mass: as given, or 2 wheel_load / g less the frame [kg].
inline double bogie_body_mass_kg(const BogieSettings& s, double wheel_load_N, double gravity_m_per_s2) {
  return s.body_mass_kg.value_or(2.0 * wheel_load_N / gravity_m_per_s2 - s.frame_mass_kg);
}

}  // namespace railjoint
