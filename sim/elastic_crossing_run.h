#pragma once
// The stepping loop of a force run (CrossingModel::elastic()): Hertz's
// contact, maybe on the lumped elastic track and under a primary suspension.
// (model) => (trajectory, track states).
//
// Bullet integrates every body (wheel, rail mass, sleeper, sprung mass; each
// moves vertically only) with its semi-implicit Euler step; the forces are
// applied by this loop before each step: Hertz (Hunt-Crossley) on each rail's
// contact from the exact narrow phase (cylinder_rail_contact.h, the same
// one the rigid runs hand to Bullet's solver), the pad, ballast and
// suspension springs and dampers, gravity and the static load. Bullet's own
// contact solver is kept out: its contacts are velocity constraints, and a
// force law needs the force itself. The track is one of force_run_track.h's
// types, the load on the wheel one of force_run_vehicle.h's; the loop is
// written once against their interface, as stages that say what they read
// and write (elastic_crossing_run.cpp).

#include "sim/crossing_model.h"
#include "sim/crossing_run.h"

namespace railjoint {

/// Runs the crossing at the force model's fixed step (ElasticCrossingSettings::time_step_s).
/// The contacts of each sample are those of the step that ended there, with
/// the impulse F dt of the force applied over it; run.track_states holds the
/// track beside each sample.
CrossingRun run_elastic_crossing(const CrossingModel& model);

}  // namespace railjoint
