#pragma once
// Jenkins's lumped track in a force run (LumpedTrackSettings): one rigid
// rail mass on a pad, a sleeper mass on ballast, vertical displacements from
// the unloaded track. Two Bullet bodies, integrated by the run's world with
// the wheel; this class applies their springs' forces. The interface is the
// one every track of force_run_track.h has.

#include <btBulletDynamicsCommon.h>

#include "sim/elastic_track_settings.h"
#include "sim/force_outcome.h"
#include "sim/vertical_body.h"

namespace railjoint {

class LumpedTrack {
 public:
  /// Adds the rail and sleeper to `world` at rest at the given displacements
  /// (their own weights rest on the springs and change nothing in the motion).
  LumpedTrack(btDiscreteDynamicsWorld& world, const LumpedTrackSettings& settings, const TrackState& start)
      : s_(settings),
        rail_(world, std::make_unique<btSphereShape>(0.05), settings.rail_mass_kg, btVector3(0, 0, start.rail_z_m),
              btVector3(0, 0, 0)),
        sleeper_(world, std::make_unique<btSphereShape>(0.05), settings.support.sleeper_mass_kg,
                 btVector3(0, 0, start.sleeper_z_m), btVector3(0, 0, 0)) {}

  /// Jenkins's own track: m_T1 = rail mass, m_T = rail + sleeper mass,
  /// K_T = pad and ballast in series, C_T = ballast damping.
  static JenkinsTrack jenkins_equivalent(const LumpedTrackSettings& settings) {
    return {settings.rail_mass_kg, settings.rail_mass_kg + settings.support.sleeper_mass_kg,
            settings.support.series_stiffness_N_per_m(), settings.support.ballast_damping_N_s_per_m};
  }

  /// The rail moves as a whole: the same everywhere [m, m/s, -].
  double deflection_m(double) const { return rail_.z_m(); }
  double deflection_rate_m_per_s(double) const { return rail_.zdot_m_per_s(); }
  double deflection_slope(double) const { return 0.0; }
  TrackState state_under(double) const { return {rail_.z_m(), sleeper_.z_m(), 0.0}; }

  /// Adds the wheel's downward force for the next step.
  void press(double, double force_N) { pressed_N_ += force_N; }
  /// (rail, sleeper, pressed force) => (forces on the rail and sleeper bodies);
  /// the world's step integrates them.
  void step(double) {
    const TrackSupportSettings& support = s_.support;
    const double pad_m = sleeper_.z_m() - rail_.z_m();
    const double pad_rate_m_per_s = sleeper_.zdot_m_per_s() - rail_.zdot_m_per_s();
    const double pad_N =
        spring_damper_N(support.pad_stiffness_N_per_m, support.pad_damping_N_s_per_m, pad_m, pad_rate_m_per_s);
    const double ballast_N = spring_damper_N(support.ballast_stiffness_N_per_m, support.ballast_damping_N_s_per_m,
                                             -sleeper_.z_m(), -sleeper_.zdot_m_per_s());
    rail_.push_up(-pressed_N_ + pad_N);
    sleeper_.push_up(-pad_N + ballast_N);
    pressed_N_ = 0.0;
  }

  /// Kinetic and elastic energy of rail and sleeper [J]; what pad and ballast dissipate [W].
  double energy_J() const {
    const TrackSupportSettings& support = s_.support;
    const double pad_m = sleeper_.z_m() - rail_.z_m();
    return 0.5 * s_.rail_mass_kg * rail_.zdot_m_per_s() * rail_.zdot_m_per_s() +
           0.5 * support.sleeper_mass_kg * sleeper_.zdot_m_per_s() * sleeper_.zdot_m_per_s() +
           0.5 * support.pad_stiffness_N_per_m * pad_m * pad_m +
           0.5 * support.ballast_stiffness_N_per_m * sleeper_.z_m() * sleeper_.z_m();
  }
  double dissipation_W() const {
    const TrackSupportSettings& support = s_.support;
    const double pad_rate_m_per_s = sleeper_.zdot_m_per_s() - rail_.zdot_m_per_s();
    return support.pad_damping_N_s_per_m * pad_rate_m_per_s * pad_rate_m_per_s +
           support.ballast_damping_N_s_per_m * sleeper_.zdot_m_per_s() * sleeper_.zdot_m_per_s();
  }

 private:
  LumpedTrackSettings s_;
  VerticalBody rail_;
  VerticalBody sleeper_;
  double pressed_N_ = 0.0;  ///< the wheel's force for the next step
};

}  // namespace railjoint
