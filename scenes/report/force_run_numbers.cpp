#include "scenes/report/force_run_numbers.h"

#include <limits>

namespace railjoint {

ForceRunNumbers force_run_numbers(const SimulationResult& result) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const ForceOutcome& f = *result.inertial()->forces;
  ForceRunNumbers n;
  n.verdict = result.verdict.ok ? "ok" : result.verdict.reason;
  n.static_N = f.static_N;
  n.p1_N = f.p1_N;
  n.p1_time_s = f.p1_time_s;
  n.p2_N = f.p2 ? f.p2->force_N : nan;
  n.p2_time_s = f.p2 ? f.p2->time_s : nan;
  n.jenkins_p1_N = f.jenkins.p1_N.value_or(nan);
  n.jenkins_p2_N = f.jenkins.p2_N.value_or(nan);
  n.p2_rail_seat_N = f.support ? f.support->p2_rail_seat_N : nan;
  n.rail_seat_peak_N = f.support ? f.support->rail_seat_peak_N : nan;
  n.ballast_peak_N = f.support ? f.support->ballast_peak_N : nan;
  n.p2_after_p1 = f.p2_after_p1;
  n.p2_across_flight = f.p2_across_flight;
  n.flights = f.flights;
  n.flight_time_s = f.flight_time_s;
  n.longest_flight_s = f.longest_flight_s;
  const std::optional<JenkinsTrack>& track = f.jenkins.track;
  n.reading_m_T1_kg = track ? track->track_mass_p1_kg : nan;
  n.reading_m_T_kg = track ? track->track_mass_p2_kg : nan;
  n.reading_K_T_N_per_m = track ? track->track_stiffness_N_per_m : nan;
  n.reading_C_T_N_s_per_m = track ? track->track_damping_N_s_per_m : nan;
  n.steps = result.steps;
  n.cpu_s = result.wall_seconds;
  return n;
}

}  // namespace railjoint
