#pragma once
// The discrete track's moving periodic state: a wheel rolled in on the
// level rail before a force run starts. The static state under a load that
// moves on (DiscreteTrack::rest_under) leaves out what the rolling wheel
// does to a track on discrete supports: the rail's stiffness under it
// changes with every sleeper it passes, so wheel and track vibrate at the
// sleeper-passing frequency v / s (the contact force 2e-3, 4e-3 and 1e-2 of
// P0 off P0 at 20, 50 and 80 m/s), and a run started in the static state
// rang with the difference in the track's P2 mode (e-fold 26 ms) on into
// the impact: a 0.05 m cosine dip at 50 m/s moved P1 and P2 by 0.14 % and
// 0.23 % between starts 1.69 and 3.33 m out (docs/forces.md, "Where a
// force run on a curved dip starts"). Rolled in long enough, that ringing
// has died out and what is left repeats at every sleeper: the run starts in
// it. The track is linear, so each wheel of a bogie is rolled in alone and
// their motions added (what one wheel's vibration does to the other's
// contact is left out: small times small).

#include "sim/discrete_track.h"
#include "sim/elastic_track_settings.h"
#include "sim/force_outcome.h"

namespace railjoint {

/// A wheel on the level rail: where its contact meets the rail, its mass,
/// and the constant load on it (the vehicle's share and its own weight, W).
struct RollingWheel {
  double contact_x_m = 0.0;
  double mass_kg = 0.0;
  double load_N = 0.0;
};

/// What rolling in left beyond the moving static state at the wheel's
/// place: the track's motion (DiscreteTrack::add_motion with track_x0_m
/// and shift_m), the wheel's height and vertical rate, and its vertical
/// contact force at the end (the periodic state's: the run's first step is
/// held to it, self_check.cpp).
struct RolledIn {
  DiscreteTrack::Motion track;
  double track_x0_m = 0.0;
  double shift_m = 0.0;
  double wheel_z_m = 0.0;
  double wheel_zdot_m_per_s = 0.0;
  double contact_force_N = 0.0;
  int steps = 0;
};

/// How long a wheel rolls in [s]: kRollInEFolds e-folds of the track's P2
/// mode, the slowest of the start's ringing to decay, its decay time taken
/// as the equivalent lumped track's (Jenkins's reading,
/// DiscreteTrack::jenkins_equivalent) 2 (m_T + M) / C_T: 19 ms on the
/// defaults, against the 26 ms measured (docs/forces.md).
double roll_in_duration_s(const JenkinsTrack& track, double wheel_mass_kg);

/// Rolls `wheel` at `speed` over a continuous rail with `settings`' supports
/// for `duration_s`, in whole sleeper bays, by the run's own velocity Verlet
/// step of `step_s`, the contact Hertz's with constant `hertz_constant` along
/// a normal whose vertical part is `normal_z` (the start's: the incoming
/// slope's, the head's lean across), started in the moving static state
/// (rest_under) with the wheel sunk by Hertz's approach. The track is a
/// treadmill: 8 decay lengths each side of the wheel, its motion moved back
/// a bay each time the wheel passes one, so the state depends on where the
/// wheel stands among the sleepers only. With a joint in `settings` (joint
/// bars or a free hinge) that periodic state is reached 3 decay lengths
/// (whole bays) further back, and the wheel rolls on from there to its place
/// over a track with the joint: the moving static state holds the joint's
/// part of the line as if the track answered at once, where it lags (its
/// dampers, its mass), and the difference rang on into the impact
/// (docs/forces.md). The motion beyond the moving static state is handed
/// over as `track`, tapered over its track's last 3 decay lengths each side.
RolledIn roll_in(const DiscreteTrackSettings& settings, const RollingWheel& wheel, double hertz_constant,
                 double normal_z, double speed_m_per_s, double step_s, double duration_s);

}  // namespace railjoint
