#pragma once
// The one stepping loop of a crossing, for both modes: builds the Bullet
// world of a CrossingModel and steps it to the end of the run, each step's
// length chosen by StepControl and cut short at the first touch of a closing
// contact (event_located_step.h), recording every step. What happened in the
// run is for the analyses (crossing_analysis.h) to find. No Bullet in this
// header.

#include <optional>
#include <vector>

#include "sim/crossing_model.h"
#include "sim/force_outcome.h"
#include "sim/trajectory.h"

namespace railjoint {

struct CrossingRun {
  Trajectory trajectory;  ///< every step, with its contacts (impacts not yet filled in)
  int steps = 0;
  int refined_steps = 0;  ///< steps at or below sim.refined_time_step
  /// Largest overlap of wheel and rail over the run [m].
  double max_penetration_m = 0.0;
  /// Gravity and load on the wheel (< 0) [N].
  double vertical_external_force_N = 0.0;
  /// Force runs only: the track beside each sample (empty otherwise).
  std::vector<TrackState> track_states;
  /// Force runs with more than one wheel (a bogie): each wheel's vertical
  /// contact force beside each sample, the leading wheel's first [N].
  std::vector<std::vector<double>> wheel_contact_force_N;
  /// Discrete-track force runs: the supports nearest the joint, each step.
  std::vector<SupportHistory> supports;
  /// Discrete-track force runs: the track as Jenkins's formulas read it (DiscreteTrack::jenkins_equivalent).
  std::optional<JenkinsTrack> discrete_track_equivalent;
  /// Discrete-track force runs: the leading wheel's vertical contact force in
  /// the periodic state the run starts in (discrete_track_roll_in.h) [N].
  std::optional<double> start_contact_force_N;
  /// Force runs only: the energy balance's largest surplus over the run [J]:
  /// mechanical energy now, less at the start, less the carrier's work, plus
  /// what the dampers took. A stable step keeps it near 0 (it swings by the
  /// step's error); a growing one is energy the integration made.
  double energy_surplus_J = 0.0;
};

CrossingRun run_crossing(const CrossingModel& model);

}  // namespace railjoint
