#pragma once
// How long each step of a crossing is. A step's length matters only where
// the wheel's path curves (sim/DESIGN.md "How the error floor was removed"): impacts are located in time
// (event_located_step.h), on a plane the motion is straight, and in flight
// the velocity Bullet records is exact whatever the step. So:
// - coarse (sim.time_step) while the wheel rolls on a plane or flies;
// - as a contact on a rail the wheel is not on closes: a quarter of the time
//   it needs to close (never below the fine step), so the approach to an
//   impact takes a handful of steps before its first touch is located;
// - fine (sim.refined_time_step) for the step that carries a located impact
//   (a coarse one solved it with the load of a whole coarse step in the
//   solver's iterations: -0.12 % on the thesis's 0.3 m step), while the wheel
//   turns about a contact (a
//   pivot about a corner: a step along the tangent leaves the arc by
//   (v dt)^2 / 2R, 2.6 mm at 1e-4 s and 50 m/s), and for sim.refine_hold
//   after; from the start, until the path is known (a landing's approach may
//   begin on a pivot); and as the wheel nears the end of the incoming rail or
//   the entry kink of a flat approach, where a pivot is about to begin;
// - but below 50 m/s, while the wheel turns about a contact the load holds
//   it on with a margin, the step that turns it by the fine step's angle at
//   50 m/s, v dt / R: what a turn's step must resolve is its angle (the
//   tangent's drift off the arc, (v dt)^2 / 2R, and the velocity's lag
//   along it), not its time (an 8.7 mm step down at 2.6 m/s, the run
//   covering the pivot's last 19.4 ms, took 19,421 steps of 1e-6 s; at
//   1.9e-5 s, 1,080 and the same jump to 3e-10);
// - and in kinematic mode, before a landing that follows a pivot shorter
//   than 8 fine steps, finer still: 8 steps over the pivot (a pivot of
//   1.8 us stepped at 1 us landed with its approach velocity 2.3e-3 of the
//   jump off the path; at 2.5e-7 s on the path to 1e-7).

#include <vector>

#include "sim/crossing_model.h"
#include "sim/trajectory.h"

namespace railjoint {

/// A contact closes when its gap shrinks faster than this fraction of the
/// horizontal speed. The exact narrow phase gives resting contacts a normal
/// velocity of round-off; the slowest landings seen close at 2e-3 v (43 N s
/// at 31 m/s after a scenario-2 flight).
inline constexpr double kClosingSpeedFraction = 1e-5;

/// The rails (by ContactSample::rail_index) on which the solver took a
/// contact in one of the last three steps. A contact on such a rail is the
/// wheel rolling on it or turning about its corner, not an impact: a pivot's
/// contact opens by the arc's rise over a step, (v dt)^2 / 2R, and closes
/// again one or two steps later (seen every other step at 1e-6 s above
/// about 30 m/s, in runs of two on the step-down side at 56 m/s).
struct RailsInContact {
  unsigned mask = 0;
  bool has(int rail) const { return rail >= 0 && rail < 32 && ((mask >> rail) & 1u) != 0; }
  static RailsInContact of(const WheelSample& sample);
  static RailsInContact of_last(const std::vector<WheelSample>& samples, std::size_t count = 3);
};

/// Below this speed a turn about a contact is stepped by the angle the fine
/// step turns at it [m/s]: the top of the thesis's table 4.1, where the
/// validation set runs at sim.refined_time_step.
inline constexpr double kTurnReferenceSpeed_m_per_s = 50.0;

/// A turn takes turn steps while its contacts carry at least this fraction
/// of the load (a kinematic wheel's, pressed on by twice the pivot's demand:
/// (g + v^2/R) / (g + 2 v^2/R) of it, about half at speed and near 1 at low
/// speed; an inertial wheel's falls to 0 as it lifts off).
inline constexpr double kTurnHeldLoadFraction = 0.25;

class StepControl {
 public:
  /// `vertical_external_force_N`: gravity and load on the wheel (< 0) [N].
  StepControl(const CrossingModel& model, double vertical_external_force_N);

  /// The step to take from `time_s` [s] (the caller cuts it at the run's end).
  double next_step_s(double time_s) const;
  /// Takes in the step of dt_s [s] that ended at samples.back(); `located`:
  /// it was cut short to end at the first touch of a contact (the next step
  /// carries the impact).
  void after_step(const std::vector<WheelSample>& samples, double dt_s, bool located);
  /// Rails the wheel is on: their contacts are no impacts to locate.
  RailsInContact engaged() const { return engaged_; }

 private:
  const CrossingModel& model_;
  double fine_step_s_ = 0.0;  ///< sim.refined_time_step, or finer to resolve a short pivot before a landing
  double flight_acceleration_m_per_s2_ = 0.0;
  double turn_step_s_ = 0.0;  ///< while the wheel turns about a contact the load holds it on
  double refine_until_s_ = 0.0;
  double turn_until_s_ = 0.0;
  double next_dt_s_ = 0.0;
  RailsInContact engaged_;
};

}  // namespace railjoint
