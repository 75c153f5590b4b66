#include "models/impact_prediction.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/finite_width_wheel.h"
#include "models/inclined_joint.h"
#include "models/parameter_checks.h"
#include "models/slice_profile.h"
#include "models/step_joint.h"
#include "models/wheel_rail_envelope.h"
#include "models/wheel_tread.h"
#include "support/input_error.h"

namespace railjoint {

const char* to_string(ImpactScenario scenario) {
  switch (scenario) {
    case ImpactScenario::one: return "1";
    case ImpactScenario::two: return "2";
    case ImpactScenario::step: return "step";
  }
  return "?";
}

namespace {

// Fills the exact part from the profile solve: position, contact points A and
// B, x_A and alpha, the one-sided vertical velocities and the exact jump.
void fill_exact(ImpactPrediction& p, const SliceProfile& profile, const WheelParams& wheel) {
  const TwoPointContact contact = solve_two_point_contact(profile, wheel.radius_m);
  const double y = p.governing_y_m;
  p.impact_wheel_x_m = contact.centre_x_m;
  p.impact_wheel_z_m = contact.centre_z_m;
  // On a step down the wheel pivots over the incoming rail's edge and lands on
  // the outgoing rail: A (the edge) is then behind the centre line.
  p.on_landing = contact.incoming.at_corner && !contact.outgoing.at_corner;
  const SegmentSupport& a = p.on_landing ? contact.incoming : contact.outgoing;
  const SegmentSupport& b = p.on_landing ? contact.outgoing : contact.incoming;
  p.contact_A_m = {a.contact_m.x(), y, a.contact_m.y()};
  p.contact_B_m = {b.contact_m.x(), y, b.contact_m.y()};
  p.x_A_m = std::abs(a.contact_m.x() - contact.centre_x_m);
  p.alpha_rad = std::asin(std::min(1.0, p.x_A_m / wheel.radius_m));  // x_A <= R up to round-off
  p.zdot_before_m_per_s = wheel.speed_m_per_s * contact.incoming.slope;
  p.zdot_after_m_per_s = wheel.speed_m_per_s * contact.outgoing.slope;
  p.impulse.exact_Ns = wheel.mass_kg * (p.zdot_after_m_per_s - p.zdot_before_m_per_s);
}

// The general model's answer: the envelope over the wheel's slices
// (wheel_rail_envelope.h). The thesis's printed and small-angle forms, its
// x_A and configurations belong to its own geometry and are left out (NaN,
// reported as null); y_t is kept where the head is flat, the tread a cylinder
// and the dip linear (only the gap sent the case here).
ImpactPrediction predict_general(const JointParams& joint, const WheelParams& wheel) {
  const EnvelopeContact contact = solve_envelope_contact(joint, wheel);
  if (!std::isfinite(contact.incoming.centre_z_m) || !std::isfinite(contact.outgoing.centre_z_m)) {
    // No x where both rails reach the wheel: the gap along the track,
    // g / sin(theta), is wider than the wheel spans there (fuzzing found
    // theta = 0.22 deg, g = 6 mm: 1.56 m). It falls in: no crossing to model.
    throw InputError("joint.gap", "the end-post gap is " + metres_text(2.0 * gap_half_shift_m(joint)) +
                                      " long along the track (gap / sin(theta)): the wheel falls into it and never "
                                      "touches both rails; use a smaller gap or a larger theta_deg");
  }
  ImpactPrediction p;
  p.impact_wheel_x_m = contact.centre_x_m;
  p.impact_wheel_z_m = contact.centre_z_m;
  // On a step down the wheel pivots over the incoming rail's edge and lands
  // on the outgoing rail: A (the edge) is then behind the centre line.
  p.on_landing = contact.incoming.at_cut_edge && !contact.outgoing.at_cut_edge;
  const RailSupport& a = p.on_landing ? contact.incoming : contact.outgoing;
  const RailSupport& b = p.on_landing ? contact.outgoing : contact.incoming;
  if (joint.kind == JointKind::step) {
    p.scenario = ImpactScenario::step;
  } else {
    p.scenario = a.at_cut_edge ? ImpactScenario::two : ImpactScenario::one;
  }
  // Where the impulse acts: A, the far rail's edge or top it meets, or on a
  // landing B, where the wheel lands after pivoting over the near edge A.
  p.governing_y_m = (p.on_landing ? b : a).contact_m.y();
  p.contact_A_m = a.contact_m;
  p.contact_B_m = b.contact_m;
  p.x_A_m = std::abs(a.contact_m.x() - contact.centre_x_m);
  p.alpha_rad = std::asin(std::min(1.0, p.x_A_m / tread_radius_m(wheel, a.contact_m.y())));
  p.zdot_before_m_per_s = wheel.speed_m_per_s * contact.incoming.slope;
  p.zdot_after_m_per_s = wheel.speed_m_per_s * contact.outgoing.slope;
  p.impulse.exact_Ns = wheel.mass_kg * (p.zdot_after_m_per_s - p.zdot_before_m_per_s);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  p.transition_y_m = has_thesis_geometry(joint, wheel) && joint.kind == JointKind::inclined
                         ? transition_y_m(joint, wheel.radius_m)
                         : kNaN;
  p.x_A_thesis_m = p.alpha_thesis_rad = kNaN;
  p.impulse.thesis_Ns = p.impulse.small_angle_Ns = kNaN;
  return p;
}

ImpactPrediction predict_step(const JointParams& joint, const WheelParams& wheel) {
  ImpactPrediction p;
  p.scenario = ImpactScenario::step;
  p.governing_y_m = wheel.lateral_m;
  fill_exact(p, slice_profile(joint, wheel.lateral_m), wheel);
  const double R = wheel.radius_m;
  const double u0 = std::abs(joint.step_height_m);  // a step down is the time reverse of a step up
  const double Mv = wheel.mass_kg * wheel.speed_m_per_s;
  p.x_A_thesis_m = step_edge_distance_large_R_m(R, u0);
  p.alpha_thesis_rad = std::asin(std::min(1.0, p.x_A_thesis_m / R));
  p.impulse.thesis_Ns = wheel.mass_kg * step_zdot_after_thesis(R, u0, wheel.speed_m_per_s);
  p.impulse.small_angle_Ns = Mv * std::sqrt(2.0 * u0 / R);
  return p;
}

ImpactPrediction predict_inclined(const JointParams& joint, const WheelParams& wheel) {
  ImpactPrediction p;
  const SliceSelection selection = select_governing_slice(joint, wheel);
  p.transition_y_m = transition_y_m(joint, wheel.radius_m);
  p.governing_y_m = selection.governing_y_m;
  p.configuration = selection.configuration;
  p.line_contact_length_m = selection.line_contact_length_m;
  p.scenario = selection.scenario_one ? ImpactScenario::one : ImpactScenario::two;
  fill_exact(p, slice_profile(joint, p.governing_y_m), wheel);

  const double Mv = wheel.mass_kg * wheel.speed_m_per_s;
  const double half_beta = joint.beta_rad / 2.0;
  p.x_A_thesis_m = x_A_thesis_m(joint, wheel.radius_m, p.governing_y_m);
  p.alpha_thesis_rad = std::asin(p.x_A_thesis_m / wheel.radius_m);
  if (p.scenario == ImpactScenario::one) {
    p.impulse.thesis_Ns = 2.0 * Mv * std::sin(half_beta);  // eq. 3.11 jump, sin form
    p.impulse.small_angle_Ns = Mv * joint.beta_rad;         // eq. 3.13
  } else {
    p.impulse.thesis_Ns = Mv * (std::sin(p.alpha_thesis_rad) + std::sin(half_beta));  // eqs. 3.24-3.25
    p.impulse.small_angle_Ns = Mv * (p.alpha_rad + half_beta);                        // eq. 3.28 with the exact alpha
  }
  return p;
}

}  // namespace

ImpactPrediction predict_impact(const JointParams& joint, const WheelParams& wheel) {
  check_parameters(joint, wheel);
  ImpactPrediction p = !governing_slice_rule_holds(joint, wheel) ? predict_general(joint, wheel)
                       : joint.kind == JointKind::step ? predict_step(joint, wheel)
                                                       : predict_inclined(joint, wheel);
  if (is_level_joint(joint) && joint.gap_m == 0.0) {
    // Level rail (to within the solve's round-off, see is_level_joint): the
    // two-point "contact" is anywhere along the flat; the answer is no jump.
    p.x_A_m = p.alpha_rad = 0.0;
    p.zdot_before_m_per_s = p.zdot_after_m_per_s = 0.0;
    p.impulse = ImpulseForms{};
  }
  return p;
}

}  // namespace railjoint
