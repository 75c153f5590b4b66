#pragma once
// The bogie of [vehicle] model = "bogie" (bogie_settings.h) as a force run's
// vehicle (force_run_vehicle.h): a frame that bounces and pitches on a
// primary spring and damper above each wheel, and a car body share on the
// secondary spring and damper at the frame's centre. Wheel 0 leads, a half
// axle spacing ahead of the frame's centre; wheel 1 trails as far behind.
// Every body is a VerticalMass (the pitch one too: its "mass" the pitch
// inertia, its "z" the angle, nose up +), stepped by the run's velocity
// Verlet. Displacements are counted from the start, where the suspensions
// carry the static loads (as SprungMass's): each primary is preloaded by
// the wheel's static load, and the frame and body, their weights borne by
// those preloads, start at rest. Small pitch angles: the frame's point
// above wheel k moves by z_f + a_k theta.

#include <array>
#include <cstddef>
#include <span>

#include "sim/bogie_settings.h"
#include "sim/vertical_mass.h"

namespace railjoint {

class Bogie {
 public:
  static constexpr std::size_t kWheels = 2;

  /// `wheels` at the start (their heights are the primaries' unstrained
  /// reference). Frame and body move with them (down the incoming slope:
  /// the frame bounces at the wheels' mean rate and pitches at their
  /// difference over the spacing), so no damper acts at the start.
  Bogie(const BogieSettings& settings, double static_load_N, double body_mass_kg, std::span<const VerticalMass> wheels)
      : s_(settings),
        static_load_N_(static_load_N),
        frame_(settings.frame_mass_kg, 0.0, 0.5 * (wheels[0].zdot_m_per_s + wheels[1].zdot_m_per_s)),
        pitch_(settings.frame_pitch_inertia_kg_m2, 0.0,
               (wheels[0].zdot_m_per_s - wheels[1].zdot_m_per_s) / settings.axle_spacing_m),
        body_(body_mass_kg, 0.0, frame_.zdot_m_per_s) {
    for (std::size_t k = 0; k < kWheels; ++k) wheel_start_z_m_[k] = wheels[k].z_m;
  }

  /// Wheel k's lever arm about the frame's centre, + ahead [m].
  double arm_m(std::size_t k) const { return k == 0 ? 0.5 * s_.axle_spacing_m : -0.5 * s_.axle_spacing_m; }

  /// (wheels) => (the downward load on each: its static load and its primary's force).
  void loads_N(std::span<const VerticalMass> wheels, std::span<double> out) const {
    for (std::size_t k = 0; k < kWheels; ++k) out[k] = static_load_N_ + primary_N(wheels[k], k);
  }
  void advance(double dt_s) {
    frame_.advance(dt_s);
    pitch_.advance(dt_s);
    body_.advance(dt_s);
  }
  /// (the loads on the wheels) => (the primaries' push on the frame, its
  /// moment, the secondary between frame and body; their half kicks).
  void accelerate(std::span<const double> loads_N, double half_step_s) {
    double up_N = 0.0;
    double moment_N_m = 0.0;
    for (std::size_t k = 0; k < kWheels; ++k) {
      const double dynamic_N = loads_N[k] - static_load_N_;
      up_N += dynamic_N;
      moment_N_m += arm_m(k) * dynamic_N;
    }
    const double secondary = secondary_N();
    frame_.accelerate(up_N - secondary, half_step_s);
    pitch_.accelerate(moment_N_m, half_step_s);
    body_.accelerate(secondary, half_step_s);
  }
  /// The static loads' potential on the wheels, the springs' energy, the
  /// frame's and body's kinetic energy [J] (a constant off the true total).
  double energy_J(std::span<const VerticalMass> wheels) const {
    double e = 0.0;
    for (std::size_t k = 0; k < kWheels; ++k) {
      const double c = primary_compression_m(wheels[k], k);
      e += static_load_N_ * wheels[k].z_m + 0.5 * s_.primary_stiffness_N_per_m * c * c;
    }
    const double cs = frame_.z_m - body_.z_m;
    return e + 0.5 * s_.secondary_stiffness_N_per_m * cs * cs + kinetic_J(frame_) + kinetic_J(pitch_) + kinetic_J(body_);
  }
  double dissipation_W(std::span<const VerticalMass> wheels) const {
    double p = 0.0;
    for (std::size_t k = 0; k < kWheels; ++k) {
      const double rate = primary_rate_m_per_s(wheels[k], k);
      p += s_.primary_damping_N_s_per_m * rate * rate;
    }
    const double rate = frame_.zdot_m_per_s - body_.zdot_m_per_s;
    return p + s_.secondary_damping_N_s_per_m * rate * rate;
  }
  /// The frame's bounce from its start [m] (a sample's sprung_z_m).
  double sprung_z_m() const { return frame_.z_m; }
  double pitch_rad() const { return pitch_.z_m; }
  double body_z_m() const { return body_.z_m; }

 private:
  static double kinetic_J(const VerticalMass& b) { return 0.5 * b.mass_kg * b.zdot_m_per_s * b.zdot_m_per_s; }
  double primary_compression_m(const VerticalMass& wheel, std::size_t k) const {
    return (wheel.z_m - wheel_start_z_m_[k]) - (frame_.z_m + arm_m(k) * pitch_.z_m);
  }
  double primary_rate_m_per_s(const VerticalMass& wheel, std::size_t k) const {
    return wheel.zdot_m_per_s - (frame_.zdot_m_per_s + arm_m(k) * pitch_.zdot_m_per_s);
  }
  double primary_N(const VerticalMass& wheel, std::size_t k) const {
    return spring_damper_N(s_.primary_stiffness_N_per_m, s_.primary_damping_N_s_per_m,
                           primary_compression_m(wheel, k), primary_rate_m_per_s(wheel, k));
  }
  // The secondary's push, frame down and body up (compressed as the frame rises towards the body).
  double secondary_N() const {
    return spring_damper_N(s_.secondary_stiffness_N_per_m, s_.secondary_damping_N_s_per_m, frame_.z_m - body_.z_m,
                           frame_.zdot_m_per_s - body_.zdot_m_per_s);
  }

  BogieSettings s_;
  double static_load_N_;
  std::array<double, kWheels> wheel_start_z_m_{};
  VerticalMass frame_;
  VerticalMass pitch_;
  VerticalMass body_;
};

}  // namespace railjoint
