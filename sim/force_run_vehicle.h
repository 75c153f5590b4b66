#pragma once
// What rides on the wheels in a force run (elastic_crossing_run.h): a constant
// static load, a sprung mass on the primary suspension
// (PrimarySuspensionSettings), or a bogie over two wheels (bogie.h). One
// interface over the run's wheels (one, or the bogie's two), picked once per run:
//   loads_N(wheels, out)          the downward load on each wheel at the step's
//                                 end (the bodies above take the opposite forces);
//   advance(dt), accelerate(loads, dt/2)  the bodies' Verlet step
//                                 (vertical_mass.h);
//   energy_J(wheels)              the loads' potential (and the suspensions'
//                                 and bodies' energy) [J];
//   dissipation_W(wheels)         what the suspensions' dampers take [W];
//   sprung_z_m()                  the sprung mass's (frame's) displacement from its start.

#include <span>
#include <variant>

#include "sim/bogie.h"
#include "sim/elastic_track_settings.h"
#include "sim/vertical_mass.h"

namespace railjoint {

/// The static wheel load, constant.
struct ConstantLoad {
  double static_load_N = 0.0;

  void loads_N(std::span<const VerticalMass>, std::span<double> out) const {
    for (double& load : out) load = static_load_N;
  }
  void advance(double) {}
  void accelerate(std::span<const double>, double) {}
  double energy_J(std::span<const VerticalMass> wheels) const {
    double e = 0.0;
    for (const VerticalMass& w : wheels) e += static_load_N * w.z_m;
    return e;
  }
  double dissipation_W(std::span<const VerticalMass>) const { return 0.0; }
  double sprung_z_m() const { return 0.0; }
};

/// A sprung mass above the (one) wheel, moving with it at the start; its
/// suspension, preloaded by the static load, carries it (so the sprung mass,
/// loaded by the same force, starts at rest).
class SprungMass {
 public:
  SprungMass(const PrimarySuspensionSettings& settings, double static_load_N, double mass_kg, double wheel_start_z_m,
             double vertical_velocity_m_per_s)
      : s_(settings),
        static_load_N_(static_load_N),
        wheel_start_z_m_(wheel_start_z_m),
        start_z_m_(wheel_start_z_m + 1.0),  // any height: the suspension's compression is counted from the start
        body_(mass_kg, start_z_m_, vertical_velocity_m_per_s) {}

  /// (wheel and sprung mass) => (load on the wheel).
  void loads_N(std::span<const VerticalMass> wheels, std::span<double> out) const {
    out[0] = static_load_N_ + spring_damper_N(s_.primary_stiffness_N_per_m, s_.primary_damping_N_s_per_m,
                                              compression_m(wheels[0].z_m),
                                              compression_rate_m_per_s(wheels[0].zdot_m_per_s));
  }
  void advance(double dt_s) { body_.advance(dt_s); }
  /// (the load on the wheel) => (the opposite force's acceleration of the sprung mass, its half kick).
  void accelerate(std::span<const double> loads_N, double half_step_s) {
    body_.accelerate(loads_N[0] - static_load_N_, half_step_s);
  }
  double energy_J(std::span<const VerticalMass> wheels) const {
    const double compression = compression_m(wheels[0].z_m);
    return static_load_N_ * (compression + body_.z_m) + 0.5 * s_.primary_stiffness_N_per_m * compression * compression +
           0.5 * body_.mass_kg * body_.zdot_m_per_s * body_.zdot_m_per_s;
  }
  double dissipation_W(std::span<const VerticalMass> wheels) const {
    const double rate = compression_rate_m_per_s(wheels[0].zdot_m_per_s);
    return s_.primary_damping_N_s_per_m * rate * rate;
  }
  double sprung_z_m() const { return body_.z_m - start_z_m_; }

 private:
  double compression_m(double wheel_z_m) const { return (start_z_m_ - wheel_start_z_m_) - (body_.z_m - wheel_z_m); }
  double compression_rate_m_per_s(double wheel_zdot_m_per_s) const { return wheel_zdot_m_per_s - body_.zdot_m_per_s; }

  PrimarySuspensionSettings s_;
  double static_load_N_;
  double wheel_start_z_m_;
  double start_z_m_;
  VerticalMass body_;
};

using ForceRunVehicle = std::variant<ConstantLoad, SprungMass, Bogie>;

}  // namespace railjoint
