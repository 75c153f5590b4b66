#pragma once
// What a force run (an inertial run with a Hertz contact or an elastic
// track, elastic_track_settings.h) adds to its result: the track's state at
// every recorded step and the forces track engineers design to, P1 and P2,
// beside Jenkins et al.'s estimates of them. Plain data, no Bullet.

#include <optional>
#include <vector>

#include "sim/elastic_track_settings.h"
#include "sim/hertz_patch_report.h"

namespace railjoint {

/// The track and vehicle at one recorded step, beside Trajectory::samples.
/// Displacements are from the unloaded track, positive up [m].
struct TrackState {
  double rail_z_m = 0.0;     ///< rail mass (0 on a rigid track)
  double sleeper_z_m = 0.0;  ///< sleeper mass (0 on a rigid track)
  double sprung_z_m = 0.0;   ///< sprung mass's displacement from its start (0 without a suspension)
};

/// One discrete-track support's forces at every recorded step, compression
/// +, with the weights it carries (the rail's bay on the pad, the bay and the
/// sleeper on the ballast) [N]; x_m: the sleeper's place [m].
struct SupportHistory {
  double x_m = 0.0;
  std::vector<double> rail_seat_N;
  std::vector<double> ballast_N;
  /// Its forces with the wheel's static load P0 standing on the joint (a
  /// bogie's leading wheel, the trailing one axle_spacing behind), the run's
  /// own track at rest (elastic_crossing_run.cpp) [N].
  double rail_seat_static_N = 0.0;
  double ballast_static_N = 0.0;
};

/// An elastic track as Jenkins's formulas see it: a lumped track's masses,
/// stiffness and damping (each track type gives its own: LumpedTrack,
/// DiscreteTrack::jenkins_equivalent).
struct JenkinsTrack {
  double track_mass_p1_kg = 0.0;          ///< m_T1, the mass P1 shares
  double track_mass_p2_kg = 0.0;          ///< m_T, the mass P2 shares
  double track_stiffness_N_per_m = 0.0;   ///< K_T
  double track_damping_N_s_per_m = 0.0;   ///< C_T
};

/// Jenkins's P1 and P2 from the scene's own parameters (impact_force_estimate.h).
struct JenkinsEstimate {
  double hertz_stiffness_N_per_m = 0.0;  ///< K_H, Hertz's law linearised at P0
  /// Empty for a step joint (the formulas are for a dip angle).
  std::optional<double> p1_N;
  /// Empty also on a rigid track (no track mass, stiffness or damping to take
  /// part) and for an overdamped track (the damping bracket below 0).
  std::optional<double> p2_N;
  /// The track's equivalent; empty on a rigid track.
  std::optional<JenkinsTrack> track;
  /// P2 with a public calculator's damping bracket, 1 - C_T pi / sqrt(K_T m_T)
  /// (impact_force_estimate.h), for comparison; empty where p2_N is, or
  /// where that bracket is below 0.
  std::optional<double> p2_calculator_N;
};

/// The forces a lumped track's supports carry (track_support_forces.h):
/// the rail seat (pad) and the ballast under the sleeper, with the masses'
/// weights [N, s on the run's clock].
struct TrackSupportOutcome {
  double rail_seat_static_N = 0.0;  ///< P0 + m_r g
  double ballast_static_N = 0.0;    ///< P0 + (m_r + m_s) g
  double rail_seat_peak_N = 0.0;
  double rail_seat_peak_time_s = 0.0;
  double ballast_peak_N = 0.0;
  double ballast_peak_time_s = 0.0;
  /// The rail-seat force's low-frequency peak, picked as the contact's P2 is (force_peaks.h).
  double p2_rail_seat_N = 0.0;
  double p2_rail_seat_time_s = 0.0;
  std::vector<double> rail_seat_N;  ///< per recorded step
  std::vector<double> ballast_N;
  /// The discrete track: the support whose pad, and whose ballast, carried
  /// the peak (the histories above are the pad's support's) [m].
  std::optional<double> rail_seat_peak_x_m, ballast_peak_x_m;
};

/// P2: the largest peak of the force after a zero-phase low-pass at
/// kP2CutoffFrequency_Hz, after the P1 pulse (force_peaks.h).
struct P2Peak {
  double force_N = 0.0;
  double time_s = 0.0;
  /// Period of the P2 mode, wheel and track mass on K_T (JenkinsTrack) [s];
  /// P2 is looked for up to half of it after the impact (force_peaks.h).
  double mode_period_s = 0.0;
  /// The end of that window [s, the run's clock].
  double window_end_s = 0.0;
  /// The run covered the window and ran on past the peak for the low pass's
  /// end transient to decay (force_peaks.h); false: P2 may depend on where
  /// the run ends, and the run cannot vouch for it (self_check.h).
  bool window_covered = false;
};

/// One wheel's P2 at the rail seat: the low-passed rail-seat force's top
/// within the wheel's window (track_support_forces.h) [N, s, m].
struct RailSeatP2 {
  double force_N = 0.0;
  double time_s = 0.0;
  /// The discrete track's support it was read at (the lumped track has one).
  std::optional<double> x_m;
  /// The window: on the discrete track from the wheel ahead's window end (the
  /// run's start for the leading wheel) to this wheel's contact P2 window end.
  double window_start_s = 0.0;
  double window_end_s = 0.0;
};

/// P1, P2 and the flights picked from one contact force history
/// (force_peaks.h): the run's (ForceOutcome) and each wheel's (WheelForces).
struct ContactForcePeaks {
  double p1_N = 0.0;  ///< the largest raw force
  double p1_time_s = 0.0;
  /// Only on an elastic track: a rigid one has no track mode to give one.
  std::optional<P2Peak> p2;
  /// The low-passed force's largest peak is one of its own after the P1
  /// pulse; false: P1 and P2 merged into one hump (a broad P1, as on the
  /// discrete track). The peak picker's verdict, written on a rigid track too.
  bool p2_after_p1 = false;
  /// Contact lost after the impact (force_peaks.h): flights, their total
  /// and the longest [s]; P2 picked across one is no track force.
  int flights = 0;
  double flight_time_s = 0.0;
  double longest_flight_s = 0.0;
  bool p2_across_flight = false;
};

/// One wheel's P1, P2 and flights (a bogie has two: ForceOutcome::wheels),
/// picked from its own contact force as the run's are.
struct WheelForces : ContactForcePeaks {
  /// Only on an elastic track that records its supports (both do).
  std::optional<RailSeatP2> p2_rail_seat;
};

/// The run's own P1, P2 and flights (ContactForcePeaks) are the leading wheel's.
struct ForceOutcome : ContactForcePeaks {
  double hertz_constant_m_per_N2_3 = 0.0;  ///< G in use at the start (P0)
  ForceHertzPatches hertz_patches;         ///< Hertz's law and patch at P0, P1 and P2 (force_contact_geometry.h)
  double restitution = 1.0;
  TrackModel track_model = TrackModel::rigid;
  bool elastic_track() const { return track_model != TrackModel::rigid; }
  bool suspension = false;     ///< a sprung mass on the primary suspension
  bool bogie = false;          ///< two wheels under a bogie (bogie_settings.h)
  double time_step_s = 0.0;

  double static_N = 0.0;  ///< P0 = sim.wheel_load + M g
  /// Static state the run starts from [m]: Hertz's approach G (P0 / n_z)^(2/3) (n_z the vertical part of
  /// the start contact's normal), the rail's deflection under the contact and the nearest sleeper's
  /// (the discrete track: under every wheel's load, a bogie's leading wheel's).
  double static_approach_m = 0.0;
  double static_rail_z_m = 0.0;
  double static_sleeper_z_m = 0.0;
  /// The contact force the start state is made for: P0, or on the discrete
  /// track its periodic state's (CrossingRun::start_contact_force_N) [N].
  std::optional<double> start_force_N;

  /// Steps across the P1 pulse: 1.5 x its width at half its height above P0
  /// (a half sine's base is 1.5 x its width at half height).
  double p1_pulse_steps = 0.0;
  JenkinsEstimate jenkins;
  /// The energy balance's largest surplus over the run (CrossingRun) and the
  /// scale it is judged against: the kinetic energy of the vertical velocity
  /// change the dip asks for, M (beta v)^2 / 2, and the static energy in the
  /// contact and track, P0 s0 / 2 (s0 the static sink), which keeps the scale
  /// from vanishing at walking pace [J].
  double energy_surplus_J = 0.0;
  double energy_scale_J = 0.0;

  /// The track's rail-seat and ballast forces: the lumped track's, the
  /// discrete track's peak supports (empty on a rigid track).
  std::optional<TrackSupportOutcome> support;
  /// The discrete track: every support recorded near the joint, its
  /// histories beside each recorded step (empty on other tracks).
  std::vector<SupportHistory> supports;

  /// Each wheel's forces, the leading one first (the run's own P1 and P2
  /// above are the leading wheel's): one wheel, or a bogie's two.
  std::vector<WheelForces> wheels;
  /// With more than one wheel: each one's vertical contact force per recorded step.
  std::vector<std::vector<double>> wheel_contact_force_N;

  std::vector<double> contact_force_N;  ///< total vertical contact force per recorded step
  std::vector<TrackState> track;        ///< per recorded step
};

}  // namespace railjoint
