#pragma once
// Jenkins's lumped track in a force run (LumpedTrackSettings): one rigid
// rail mass on a pad, a sleeper mass on ballast, vertical displacements from
// the unloaded track. Two vertical masses stepped with the wheel (vertical_mass.h);
// this class applies their springs' forces. The interface is the one every
// track of force_run_track.h has.

#include "sim/elastic_track_settings.h"
#include "sim/force_outcome.h"
#include "sim/vertical_mass.h"

namespace railjoint {

class LumpedTrack {
 public:
  /// The rail and sleeper at rest at the given displacements (their own
  /// weights rest on the springs and change nothing in the motion).
  LumpedTrack(const LumpedTrackSettings& settings, const TrackState& start)
      : s_(settings),
        rail_(settings.rail_mass_kg, start.rail_z_m, 0.0),
        sleeper_(settings.support.sleeper_mass_kg, start.sleeper_z_m, 0.0) {}

  /// Jenkins's own track: m_T1 = rail mass, m_T = rail + sleeper mass,
  /// K_T = pad and ballast in series, C_T = ballast damping.
  static JenkinsTrack jenkins_equivalent(const LumpedTrackSettings& settings) {
    return {settings.rail_mass_kg, settings.rail_mass_kg + settings.support.sleeper_mass_kg,
            settings.support.series_stiffness_N_per_m(), settings.support.ballast_damping_N_s_per_m};
  }

  /// The rail moves as a whole: the same everywhere [m, m/s, -].
  double deflection_m(double) const { return rail_.z_m; }
  double deflection_rate_m_per_s(double) const { return rail_.zdot_m_per_s; }
  double deflection_slope(double) const { return 0.0; }
  TrackState state_under(double) const { return {rail_.z_m, sleeper_.z_m, 0.0}; }

  /// The step's first half kick and drift (vertical_mass.h).
  void advance(double dt_s) {
    rail_.advance(dt_s);
    sleeper_.advance(dt_s);
  }
  /// Adds the wheel's downward force at the step's end.
  void press(double, double force_N) { pressed_N_ += force_N; }
  /// The rail's rate per unit impulse pressed on it anywhere [1/kg].
  double kick_mobility_per_kg(double, double) const { return 1.0 / s_.rail_mass_kg; }
  /// (rail, sleeper, pressed force) => (their accelerations, the second half kick).
  void accelerate(double half_step_s) {
    const TrackSupportSettings& support = s_.support;
    const double pad_m = sleeper_.z_m - rail_.z_m;
    const double pad_rate_m_per_s = sleeper_.zdot_m_per_s - rail_.zdot_m_per_s;
    const double pad_N =
        spring_damper_N(support.pad_stiffness_N_per_m, support.pad_damping_N_s_per_m, pad_m, pad_rate_m_per_s);
    const double ballast_N = spring_damper_N(support.ballast_stiffness_N_per_m, support.ballast_damping_N_s_per_m,
                                             -sleeper_.z_m, -sleeper_.zdot_m_per_s);
    rail_.accelerate(-pressed_N_ + pad_N, half_step_s);
    sleeper_.accelerate(-pad_N + ballast_N, half_step_s);
    pressed_N_ = 0.0;
  }

  /// Its rail seat is read from state_under (nothing to record).
  void record_supports() {}

  /// Kinetic and elastic energy of rail and sleeper [J]; what pad and ballast dissipate [W].
  double energy_J() const {
    const TrackSupportSettings& support = s_.support;
    const double pad_m = sleeper_.z_m - rail_.z_m;
    return 0.5 * s_.rail_mass_kg * rail_.zdot_m_per_s * rail_.zdot_m_per_s +
           0.5 * support.sleeper_mass_kg * sleeper_.zdot_m_per_s * sleeper_.zdot_m_per_s +
           0.5 * support.pad_stiffness_N_per_m * pad_m * pad_m +
           0.5 * support.ballast_stiffness_N_per_m * sleeper_.z_m * sleeper_.z_m;
  }
  double dissipation_W() const {
    const TrackSupportSettings& support = s_.support;
    const double pad_rate_m_per_s = sleeper_.zdot_m_per_s - rail_.zdot_m_per_s;
    return support.pad_damping_N_s_per_m * pad_rate_m_per_s * pad_rate_m_per_s +
           support.ballast_damping_N_s_per_m * sleeper_.zdot_m_per_s * sleeper_.zdot_m_per_s;
  }

 private:
  LumpedTrackSettings s_;
  VerticalMass rail_;
  VerticalMass sleeper_;
  double pressed_N_ = 0.0;  ///< the wheel's force at the step's end
};

}  // namespace railjoint
