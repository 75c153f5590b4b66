#pragma once
// The inertial mode of the crossing simulation (SimMode::inertial): the wheel
// loaded as in service, free to leave the rail. Called by simulate_crossing;
// its result carries SimulationResult::inertial. No Bullet in this header.

#include "models/parameters.h"
#include "sim/sim_settings.h"
#include "sim/simulate_crossing.h"

namespace railjoint {

/// Runs one inertial crossing. Expects settings already checked
/// (check_sim_settings, which calls check_inertial_settings).
SimulationResult simulate_inertial_crossing(const JointParams& joint, const WheelParams& wheel,
                                            const SimSettings& settings);

/// The inertial-only settings and their combinations; throws
/// InputError("sim.<key>", ...).
void check_inertial_settings(const SimSettings& settings, const JointParams& joint, const WheelParams& wheel);

/// Height of the kinematic reference path at centre x [m]: the glued wheel's
/// centre (kinematic_centre_height_m of the governing slice of `wheel`, the
/// wheel as simulated), and with a flat approach the flat before the dip and
/// the pivot over its entry kink.
double inertial_reference_height_m(const JointParams& joint, const WheelParams& wheel, double flat_approach_m,
                                   double wheel_x_m);

}  // namespace railjoint
