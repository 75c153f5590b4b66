#pragma once
// Contact and flight phases of a recorded crossing: when the wheel touched
// the rails, when it left them, how long and how high it flew, how far it
// strayed from the kinematic path, and the contact force history. Pure
// function of the recorded samples (no Bullet), so it can be tested on
// hand-made trajectories.

#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

#include "sim/trajectory.h"

namespace railjoint {

struct PhaseDetection {
  /// A sample is in contact when its contacts carried a normal impulse above
  /// this in the step that ended at it [N s/s = N, compared with impulse / dt]:
  /// a small fraction of the static load, far above solver round-off.
  double min_contact_force_N = 100.0;
  /// A run of contact-free samples is a flight only if it lasts at least this
  /// long [s] and spans at least `min_flight_samples` samples (a contact that
  /// flickers open for one step is no flight).
  double min_flight_s = 2e-5;
  int min_flight_samples = 3;
  /// ... and only if the centre rose more than this above the reference path
  /// during it [m]. A rigid contact is solved once the overlap exceeds the
  /// processing threshold (3 um) and rests at the slop (4 um): a wheel that
  /// barely holds on to a pivot chatters across that 1 um band without ever
  /// leaving the rail.
  double min_flight_clearance_m = 2e-6;
};

/// One interval of contact or of flight, in time order, covering the run.
struct ContactPhase {
  bool in_contact = true;
  double start_time_s = 0.0;
  double end_time_s = 0.0;
  double start_x_m = 0.0;
  double end_x_m = 0.0;
};

struct Flight {
  double liftoff_time_s = 0.0;   ///< last in-contact sample before the flight
  double liftoff_x_m = 0.0;
  double liftoff_z_m = 0.0;
  double liftoff_zdot_m_per_s = 0.0;
  /// First in-contact sample after it; NaN when the run ended in flight.
  double landing_time_s = std::numeric_limits<double>::quiet_NaN();
  double landing_x_m = std::numeric_limits<double>::quiet_NaN();
  bool landed = false;
  double duration_s = 0.0;       ///< landing - lift-off (to the end of the run if it did not land) [s]
  double apex_height_m = 0.0;    ///< highest centre height above the lift-off height [m]
  double apex_time_s = 0.0;
  double max_clearance_m = 0.0;  ///< largest height above the reference (kinematic) path during the flight [m]
  std::size_t first_sample = 0;  ///< first contact-free sample
  std::size_t last_sample = 0;   ///< last contact-free sample
};

/// What the phases analysis finds over a run, as InertialOutcome reports it.
struct ContactPhaseSummary {
  std::vector<ContactPhase> phases;  ///< contact and flight intervals covering the run
  std::vector<Flight> flights;
  /// The run ended before the wheel landed (lengthen run_out_time, joint.length).
  bool ended_in_flight = false;
  /// Largest |z - z_reference(x)| over the run, and where [m].
  double max_deviation_m = 0.0;
  double max_deviation_x_m = 0.0;
  /// Largest upward z - z_reference(x) [m] (flights), largest downward (sinking into a compliant contact).
  double max_rise_m = 0.0;
  double max_sink_m = 0.0;
  /// Largest summed vertical contact force of the run, when and where [N, s, m].
  double peak_force_N = 0.0;
  double peak_force_time_s = 0.0;
  double peak_force_x_m = 0.0;
};

struct ContactPhaseAnalysis : ContactPhaseSummary {
  /// Summed vertical contact force of every sample (impulse / contact_span_s) [N].
  std::vector<double> vertical_force_N;
};

/// Centre height of the reference path at centre position x [m].
using ReferenceHeight = std::function<double(double)>;

ContactPhaseAnalysis analyse_contact_phases(const Trajectory& trajectory, const ReferenceHeight& reference,
                                            const PhaseDetection& detection);

/// Summed vertical contact impulse of a sample over its step divided by the time it
/// carried the load over (contact_span_s) [N]:
/// the step that ended at it, for the first sample the one that begins there
/// (a force run records its starting state's contacts; a rigid run none, 0).
double vertical_contact_force_N(const std::vector<WheelSample>& samples, std::size_t k);

}  // namespace railjoint
