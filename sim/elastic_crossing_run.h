#pragma once
// The stepping loop of a force run (CrossingModel::elastic()): Hertz's
// contact, maybe on the lumped elastic track and under a primary suspension.
// (model) => (trajectory, track states).
//
// Every body (wheel, rail mass, sleeper, sprung mass, the discrete track's
// nodes and sleepers; each moves vertically only) is a plain state stepped by
// velocity Verlet, second order (vertical_mass.h), the dampers at the rates
// predicted at the step's end; a contact's onset is located within its step.
// A sample every sim.force_time_step; on an elastic track, over the impact's pulse, each sample's
// step is split into steps of at most sim.refined_time_step (a damped
// contact's pulse sqrt(1 + alpha) finer, on a rigid track too;
// pulse_window.h: P1 within 4.4e-6 of its converged value at the default
// step on the lumped track, 7.1e-5 without).
// The forces: Hertz (Hunt-Crossley) on each rail's contact from the exact
// narrow phase (cylinder_rail_contact.h, the same one the rigid runs hand to
// Bullet's solver), the pad, ballast and suspension springs and dampers,
// gravity and the static load. Bullet is not used: its step was semi-implicit
// Euler, first order (P1 off by -7.5e-4 at the default step on the lumped
// track), and added nothing but bookkeeping. The track is one of
// force_run_track.h's types, the load on the wheel one of
// force_run_vehicle.h's; the loop is
// written once against their interface, as stages that say what they read
// and write (elastic_crossing_run.cpp).

#include "sim/crossing_model.h"
#include "sim/crossing_run.h"

namespace railjoint {

/// Runs the crossing at the force model's fixed step (ElasticCrossingSettings::time_step_s).
/// The contacts of each sample are those of the state at its time, with the
/// impulse F dt; run.track_states holds the track beside each sample.
CrossingRun run_elastic_crossing(const CrossingModel& model);

}  // namespace railjoint
