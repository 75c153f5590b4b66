#pragma once
// What rides on the wheel in a force run (elastic_crossing_run.h): a constant
// static load, or a sprung mass on the primary suspension
// (PrimarySuspensionSettings). One interface, picked once per run:
//   load_N(wheel_z, wheel_zdot)   the downward load on the wheel this step
//                                 (the sprung mass takes the opposite force);
//   energy_J(wheel_z, wheel_zdot) the load's potential (and the suspension's
//                                 and sprung mass's energy) [J];
//   dissipation_W(wheel_zdot)     what the suspension's damper takes [W];
//   sprung_z_m()                  the sprung mass's displacement from its start.

#include <variant>

#include <btBulletDynamicsCommon.h>

#include "sim/elastic_track_settings.h"
#include "sim/vertical_body.h"

namespace railjoint {

/// The static wheel load, constant.
struct ConstantLoad {
  double static_load_N = 0.0;

  double load_N(double, double) { return static_load_N; }
  double energy_J(double wheel_z_m, double) const { return static_load_N * wheel_z_m; }
  double dissipation_W(double, double) const { return 0.0; }
  double sprung_z_m() const { return 0.0; }
};

/// A sprung mass above the wheel, moving with it at the start; its
/// suspension, preloaded by the static load, carries it (so the sprung mass,
/// loaded by the same force, starts at rest).
class SprungMass {
 public:
  SprungMass(btDiscreteDynamicsWorld& world, const PrimarySuspensionSettings& settings, double static_load_N,
             double mass_kg, const btVector3& wheel_centre_m, double vertical_velocity_m_per_s)
      : s_(settings),
        static_load_N_(static_load_N),
        wheel_start_z_m_(wheel_centre_m.z()),
        start_z_m_(wheel_centre_m.z() + 1.0),  // any height: the suspension's compression is counted from the start
        body_(world, std::make_unique<btSphereShape>(0.05), mass_kg,
              btVector3(wheel_centre_m.x(), wheel_centre_m.y(), start_z_m_),
              btVector3(0, 0, vertical_velocity_m_per_s)) {}

  /// (wheel and sprung mass) => (load on the wheel, the opposite force on the sprung mass).
  double load_N(double wheel_z_m, double wheel_zdot_m_per_s) {
    const double load_N = static_load_N_ + spring_damper_N(s_.primary_stiffness_N_per_m, s_.primary_damping_N_s_per_m,
                                                           compression_m(wheel_z_m),
                                                           compression_rate_m_per_s(wheel_zdot_m_per_s));
    body_.push_up(load_N - static_load_N_);
    return load_N;
  }
  double energy_J(double wheel_z_m, double) const {
    const double compression = compression_m(wheel_z_m);
    const double mass_kg = 1.0 / body_.body->getInvMass();
    return static_load_N_ * (compression + body_.z_m()) + 0.5 * s_.primary_stiffness_N_per_m * compression * compression +
           0.5 * mass_kg * body_.zdot_m_per_s() * body_.zdot_m_per_s();
  }
  double dissipation_W(double, double wheel_zdot_m_per_s) const {
    const double rate = compression_rate_m_per_s(wheel_zdot_m_per_s);
    return s_.primary_damping_N_s_per_m * rate * rate;
  }
  double sprung_z_m() const { return body_.z_m() - start_z_m_; }

 private:
  double compression_m(double wheel_z_m) const { return (start_z_m_ - wheel_start_z_m_) - (body_.z_m() - wheel_z_m); }
  double compression_rate_m_per_s(double wheel_zdot_m_per_s) const {
    return wheel_zdot_m_per_s - body_.zdot_m_per_s();
  }

  PrimarySuspensionSettings s_;
  double static_load_N_;
  double wheel_start_z_m_;
  double start_z_m_;
  VerticalBody body_;
};

using ForceRunVehicle = std::variant<ConstantLoad, SprungMass>;

}  // namespace railjoint
