#pragma once
// The one time origin of every output (scenes/report/outputs.md): t = 0 when
// the wheel centre passes the predicted (analytic) impact position. The
// analytic histories are built around that instant; a simulation's sample
// times are shifted by the run time at which its centre crosses that x.

#include <vector>

#include "sim/simulation_result.h"
#include "sim/trajectory.h"

namespace railjoint {

/// The run time [s] at which the centre first reaches `x_m`, linear between
/// the two samples around it (the inertial mode's speed varies); before the
/// first sample or after the last, carried on at that sample's speed.
/// `samples` must not be empty.
double passage_time_s(const std::vector<WheelSample>& samples, double x_m);

/// The run time [s] that is t = 0 in simulate's outputs: when the centre
/// passes the impact position predicted for the scene's wheel (what
/// `analytic` of the same scene puts at t = 0).
double simulation_time_origin_s(const SimulationResult& result);

/// `trajectory` with every time (samples, their velocities' instants,
/// impacts) less `origin_s`: on the outputs' clock when origin_s is
/// simulation_time_origin_s. What `render` draws, so that its frames'
/// labels and render.t_start / t_end read as the JSON's and CSV's times.
Trajectory on_output_clock(Trajectory trajectory, double origin_s);

}  // namespace railjoint
