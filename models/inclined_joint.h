#pragma once
// Closed-form geometry of the inclined dipped joint (thesis section 3.3) for a
// thin disc at lateral position y: the cut, the mismatch, the transition value
// y_t and the distance x_A of contact point A from the wheel centre line, by
// the thesis's route (appendix C) and by an exact solve. gap = 0 throughout,
// as in the thesis's global model, except gap_half_shift_m, which
// slice_profile.h and the rail meshes use to handle a gap.

#include "models/parameters.h"

namespace railjoint {

/// A square joint (theta = 90 deg to within 1e-12 rad): the cut runs straight
/// across the head, every slice sees the same joint, y_t is infinite.
bool is_square_joint(double theta_rad);

/// x of the cut at lateral y: y cot(theta) [m] (0 for a square joint).
double cut_x_m(double theta_rad, double y_m);

/// How far the end-post gap moves each rail end back from the cut, along x
/// [m]: g / (2 sin theta) for the inclined cut (the gap is measured normal to
/// it), g / 2 for the step joint.
double gap_half_shift_m(const JointParams& joint);

/// Vertical mismatch between the rail ends at lateral y, exact geometry:
/// 2 tan(beta/2) y cot(theta) [m] (positive: step up in the direction of travel).
double mismatch_height_m(const JointParams& joint, double y_m);

/// Transition value y_t = R sin(beta/2) tan(theta) [m]; +inf for a square joint.
/// |y| <= y_t is contact scenario 1, beyond it scenario 2.
double transition_y_m(const JointParams& joint, double radius_m);

/// x_A for a thin disc at lateral y, exact: distance along x from the wheel
/// centre to the far rail's corner when the centre, riding on the offset line
/// of the incoming rail top, is at distance R from that corner (scenario 2);
/// R sin(beta/2) in scenario 1. Uses |y| (the step-down side mirrors it).
double x_A_exact_m(const JointParams& joint, double radius_m, double y_m);

/// The thesis's closed form (appendix C, `a(y')` in the local frame shifted by
/// y_t, x_A = x'_joint(y') - a(y')); R sin(beta/2) in scenario 1. Uses |y|.
double x_A_thesis_m(const JointParams& joint, double radius_m, double y_m);

}  // namespace railjoint
