#pragma once
// A force run's numbers as the tables print them (`study forces`, `study
// published`, the sweep's forces columns), read from its result in one
// place. NaN where the run has none: P2 on a rigid track, Jenkins's
// formulas for a step joint, the rail seat on a track that records no
// supports, the track's reading on a rigid track.

#include <string>

#include "sim/simulation_result.h"

namespace railjoint {

struct ForceRunNumbers {
  std::string verdict;  ///< "ok" or the self-check's reason
  double static_N = 0.0;   ///< P0 [N]
  double p1_N = 0.0;
  double p1_time_s = 0.0;  ///< [s, the run's clock]
  double p2_N = 0.0;
  double p2_time_s = 0.0;  ///< [s, the run's clock]
  double jenkins_p1_N = 0.0;
  double jenkins_p2_N = 0.0;
  /// The track's P2 at the rail seat and its largest rail-seat and ballast forces [N].
  double p2_rail_seat_N = 0.0, rail_seat_peak_N = 0.0, ballast_peak_N = 0.0;
  bool p2_after_p1 = false, p2_across_flight = false;
  int flights = 0;
  double flight_time_s = 0.0, longest_flight_s = 0.0;
  /// The track as Jenkins's formulas read it (on the discrete track: its
  /// equivalent lumped track, DiscreteTrack::jenkins_equivalent).
  double reading_m_T1_kg = 0.0, reading_m_T_kg = 0.0, reading_K_T_N_per_m = 0.0, reading_C_T_N_s_per_m = 0.0;
  int steps = 0;
  double cpu_s = 0.0;  ///< the run's wall time on one core
};

/// `result` must be a force run's (InertialOutcome::forces set).
ForceRunNumbers force_run_numbers(const SimulationResult& result);

}  // namespace railjoint
