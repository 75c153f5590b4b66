#pragma once
// Checks that a joint and wheel describe a case the kinematic model covers.
// Throws InputError naming the scene key at fault.

#include "models/parameters.h"

namespace railjoint {

/// Angles, sizes and positions the model covers, each with its key, and the
/// rail extent: the two rail ends must exist on every y in [-b_t, b_t] (the
/// cut across the head and the end-post gap leave each a positive length) and
/// give the wheel `run_up_m` of travel before the cut plus its contact lead on
/// each side:
///  - incoming: run_up_m + R sin(beta/2) (the wheel on the slope touches it
///    R sin(beta/2) behind its centre line; 0 for the flat step joint);
///  - outgoing: run_up_m + R sin(alpha_max) past the cut, where
///    R sin(alpha_max) = min(R, sqrt(2 R h) + R sin(beta/2)) bounds the lead
///    x_A of the contact on the far rail (a step of height h met on a slope of
///    beta/2 leads by at most sqrt(2 R h), plus the slope's own R sin(beta/2));
///    h is the largest mismatch at the cut, 2 tan(beta/2) b_t cot(theta), or |u0|.
/// The model's slice profiles end at x = +-L/2, so run_up_m = 0 is the least
/// the analytic model needs; the simulation asks for more (check_joint_geometry).
void check_parameters(const JointParams& joint, const WheelParams& wheel, double run_up_m = 0.0);

/// The shortest rail length L whose extent check_parameters accepts with
/// `run_up_m` (the run-up, the contact leads, the cut's reach and the gap) [m].
double minimum_joint_length_m(const JointParams& joint, const WheelParams& wheel, double run_up_m = 0.0);

/// A level joint (inclined with beta < 1e-7 rad, or a step with |u0| < 1e-9 m):
/// no mismatch and no kink that double precision can resolve, so no jump.
bool is_level_joint(const JointParams& joint);

/// Throws InputError (joint.beta or joint.step_height) for a level joint:
/// a simulation of it has no jump to measure.
void check_joint_has_jump(const JointParams& joint);

}  // namespace railjoint
