#pragma once
// The forces in a lumped track (Jenkins's: a rail mass on a pad, a sleeper
// mass on ballast) at every recorded step, from its recorded displacements:
// what a strain-gauged baseplate (the rail seat) and the ballast under the
// sleeper carry. By an account quoted in issue 41 (not checked here),
// British Rail's dipped-joint tests behind Jenkins et al. (1974) measured the
// vertical force under the rail, not at the contact, so P2 is given both
// ways. Pure functions.

#include <optional>
#include <vector>

#include "sim/elastic_track_settings.h"
#include "sim/force_outcome.h"

namespace railjoint {

/// The rail-seat (pad) and ballast forces, positive in compression [N].
/// The run's displacements are from the track under its own weight (the
/// masses' weights rest on the springs and change nothing in the motion,
/// lumped_track.h), so the pad carries the rail's weight m_r g on top of
/// its spring and damper, the ballast (m_r + m_s) g: in the static state
/// P0 + m_r g and P0 + (m_r + m_s) g.
/// Velocities are the recorded displacements' backward differences, the
/// step's mean velocity (a semi-implicit Euler step's end velocity exactly);
/// the first sample, the static start, is at rest.
/// One support's forces, positive in compression [N], the lumped track's one
/// and each sleeper of the discrete track's: the pad between the rail and the
/// sleeper (displacements up +, their rates) carrying `rail_weight_N` besides,
/// and the ballast under the sleeper carrying `track_weight_N` (rail and
/// sleeper) besides.
inline double pad_force_N(const TrackSupportSettings& s, double rail_z_m, double rail_rate_m_per_s, double sleeper_z_m,
                          double sleeper_rate_m_per_s, double rail_weight_N) {
  return s.pad_stiffness_N_per_m * (sleeper_z_m - rail_z_m) +
         s.pad_damping_N_s_per_m * (sleeper_rate_m_per_s - rail_rate_m_per_s) + rail_weight_N;
}
inline double ballast_force_N(const TrackSupportSettings& s, double sleeper_z_m, double sleeper_rate_m_per_s,
                              double track_weight_N) {
  return s.ballast_stiffness_N_per_m * (-sleeper_z_m) + s.ballast_damping_N_s_per_m * (-sleeper_rate_m_per_s) +
         track_weight_N;
}

struct TrackSupportForces {
  std::vector<double> rail_seat_N;
  std::vector<double> ballast_N;
};

/// The discrete track's supports near the joint (SupportHistory, recorded
/// by the run at `time_s`): the largest rail-seat and ballast forces over
/// them, which support and when, that support's static forces, and the
/// peak rail-seat support's histories; p2_rail_seat_N is left for the
/// leading wheel's (discrete_rail_seat_p2). Empty when no support has a
/// whole history.
std::optional<TrackSupportOutcome> discrete_track_support_outcome(const std::vector<double>& time_s,
                                                                  const std::vector<SupportHistory>& supports);

/// One wheel's rail-seat P2 on the discrete track: the support whose
/// rail-seat force is largest within [from_s, to_s] (the one the wheel is
/// struck onto), and its low-passed top there (force_peaks.h's
/// lowpassed_top, at `cutoff_Hz`). The window is the wheel's own crossing:
/// it ends where the wheel's contact P2 window ends (what comes later, the
/// next crest, a landing, the next wheel, is not its P2) and opens where the
/// wheel ahead's closed (the run's start for the leading wheel), so a
/// bogie's two windows share no sample and the trailing wheel's leaves out
/// the leading wheel's hump at the same support. Empty when no support has
/// a whole history.
std::optional<RailSeatP2> discrete_rail_seat_p2(const std::vector<double>& time_s,
                                                const std::vector<SupportHistory>& supports, double from_s,
                                                double to_s, double cutoff_Hz);

TrackSupportForces lumped_track_support_forces(const std::vector<double>& time_s, const std::vector<TrackState>& track,
                                               const LumpedTrackSettings& settings, double gravity_m_per_s2);

}  // namespace railjoint
