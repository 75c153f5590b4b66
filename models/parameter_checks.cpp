#include "models/parameter_checks.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "models/inclined_joint.h"
#include "models/profile_curve.h"
#include "models/rail_head.h"
#include "models/wheel_tread.h"
#include "support/input_error.h"

namespace railjoint {

namespace {
// Largest |x| the cut line reaches across the head, without the gap [m].
double cut_reach_m(const JointParams& joint) {
  return joint.kind == JointKind::step ? 0.0 : std::abs(cut_x_m(joint.theta_rad, joint.half_width_m));
}

// Bound on the contact lead x_A over the wheel centre line [m] (see the header).
double contact_lead_bound_m(const JointParams& joint, const WheelParams& wheel) {
  const double R = wheel.radius_m;
  if (joint.kind == JointKind::step) return std::min(R, std::sqrt(2.0 * R * std::abs(joint.step_height_m)));
  // The gap moves the far rail's corner up its slope: 2 tan(beta/2) more per metre of shift.
  const double h = std::abs(mismatch_height_m(joint, joint.half_width_m)) +
                   2.0 * std::tan(joint.beta_rad / 2.0) * gap_half_shift_m(joint);
  return std::min(R, std::sqrt(2.0 * R * h) + R * std::sin(joint.beta_rad / 2.0));
}

// What the rail extent must hold (see the header): the cut's reach across the
// head, the gap's shift of each rail end, the travel before and past the cut.
struct RailExtent {
  double reach_m = 0.0;
  double shift_m = 0.0;
  double run_in_m = 0.0;
  double run_out_m = 0.0;
  double length_min_m() const { return 2.0 * (reach_m + shift_m + std::max(run_in_m, run_out_m)); }
};

RailExtent rail_extent(const JointParams& joint, const WheelParams& wheel, double run_up_m) {
  RailExtent extent;
  extent.reach_m = cut_reach_m(joint);
  extent.shift_m = gap_half_shift_m(joint);
  const double slope_lead = joint.kind == JointKind::step ? 0.0 : wheel.radius_m * std::sin(joint.beta_rad / 2.0);
  extent.run_in_m = run_up_m + slope_lead;
  extent.run_out_m = run_up_m + contact_lead_bound_m(joint, wheel);
  return extent;
}

void check_joint_extent(const JointParams& joint, const WheelParams& wheel, double run_up_m) {
  const double half_length = joint.length_m / 2.0;
  const RailExtent extent = rail_extent(joint, wheel, run_up_m);
  const double reach = extent.reach_m;
  if (!(half_length > reach)) {
    throw InputError("joint.length", "rail length L must be > 2 b_t cot(theta) = " + metres_text(2.0 * reach) +
                                             " to hold the cut across the rail head, got " + metres_text(joint.length_m));
  }
  const double shift = extent.shift_m;
  if (!(shift < half_length - reach)) {
    const double gap_max = joint.gap_m * (half_length - reach) / shift;  // the shift is proportional to the gap
    throw InputError("joint.gap", "end-post gap must be in [0, " + metres_text(gap_max) +
                                          "): a wider gap leaves no rail at y = +-b_t, got " + metres_text(joint.gap_m));
  }
  const double length_min = extent.length_min_m();
  if (!(joint.length_m >= length_min)) {
    const std::string travel = run_up_m > 0.0 ? metres_text(run_up_m) + " plus the contact lead" : "the contact lead";
    throw InputError("joint.length", "rail length L must be >= " + metres_text(length_min) +
                                             " so that on every y in [-b_t, b_t] the incoming rail gives the wheel " +
                                             metres_text(extent.run_in_m) + " before the cut and the outgoing rail " +
                                             metres_text(extent.run_out_m) + " past it (" + travel + "), got " +
                                             metres_text(joint.length_m));
  }
}

}  // namespace

double minimum_joint_length_m(const JointParams& joint, const WheelParams& wheel, double run_up_m) {
  return rail_extent(joint, wheel, run_up_m).length_min_m();
}

void check_parameters(const JointParams& joint, const WheelParams& wheel, double run_up_m) {
  if (!(joint.theta_rad > 0.0 && joint.theta_rad <= std::numbers::pi / 2.0)) {
    throw InputError("joint.theta_deg", "junction angle must be in (0, 90] deg");
  }
  if (!(joint.beta_rad >= 0.0 && joint.beta_rad < std::numbers::pi / 2.0)) {
    throw InputError("joint.beta", "dip angle must be in [0, pi/2) rad");
  }
  if (!(joint.half_width_m > 0.0 && std::isfinite(joint.half_width_m))) {
    throw InputError("joint.half_width", "rail-head half-width must be a finite length > 0 m");
  }
  if (!(joint.length_m > 0.0 && std::isfinite(joint.length_m))) {
    throw InputError("joint.length", "rail length L must be a finite length > 0 m");
  }
  if (!(joint.gap_m >= 0.0 && std::isfinite(joint.gap_m))) {
    throw InputError("joint.gap", "end-post gap must be a finite length >= 0 m");
  }
  if (!(wheel.radius_m > 0.0 && std::isfinite(wheel.radius_m))) {
    throw InputError("wheel.radius", "wheel radius must be a finite length > 0 m");
  }
  if (!(wheel.mass_kg > 0.0 && std::isfinite(wheel.mass_kg))) {
    throw InputError("wheel.mass", "wheel mass must be finite and > 0 kg");
  }
  if (!(wheel.speed_m_per_s > 0.0 && std::isfinite(wheel.speed_m_per_s))) {
    throw InputError("wheel.speed", "speed must be finite and > 0 m/s");
  }
  if (!(wheel.width_m >= 0.0 && std::isfinite(wheel.width_m))) {
    throw InputError("wheel.width", "wheel width must be a finite length >= 0 m (0 = thin disc)");
  }
  // A thin disc's plane must cross the head; a wider wheel stands on it as
  // long as some of its tread does (the model clips its span to the head).
  if (wheel.width_m == 0.0 && !(std::abs(wheel.lateral_m) <= joint.half_width_m)) {
    throw InputError("wheel.y", "lateral position must lie on the rail head, |y| <= joint.half_width = " +
                                        metres_text(joint.half_width_m) + ", got " + metres_text(wheel.lateral_m));
  }
  if (wheel.width_m > 0.0 && !(std::abs(wheel.lateral_m) < joint.half_width_m + wheel.width_m / 2.0)) {
    throw InputError("wheel.y", "the wheel must stand on the rail head: |y| < joint.half_width + width/2 = " +
                                        metres_text(joint.half_width_m + wheel.width_m / 2.0) + ", got " +
                                        metres_text(wheel.lateral_m));
  }
  if (!(joint.crown_radius_m == 0.0 || (joint.crown_radius_m > joint.half_width_m && std::isfinite(joint.crown_radius_m)))) {
    throw InputError("joint.crown_radius", "crown radius must be 0 (a flat head) or > joint.half_width = " +
                                               metres_text(joint.half_width_m) + " (the arc must span the head), got " +
                                               metres_text(joint.crown_radius_m));
  }
  if (joint.rail_profile != RailProfile::arc) {
    // A measured head is named by its file: a head that spans too little is
    // as often the file's fault (a profile in other units) as the key's.
    const std::string name = joint.rail_profile == RailProfile::en_60e1 ? "the 60E1 head"
                             : joint.measured_head                        ? "the measured head in " + joint.measured_head->source()
                                                                          : "the measured head";
    if (joint.crown_radius_m != 0.0) {
      throw InputError("joint.crown_radius", "applies to rail_profile = \"crowned\"; " + name + " has its own shape");
    }
    if (!(joint.half_width_m <= head_profile_half_width_m(joint))) {
      throw InputError("joint.half_width", name + " spans |y| <= " + metres_text(head_profile_half_width_m(joint)) +
                                               " across its top, got half-width " + metres_text(joint.half_width_m));
    }
  }
  if (wheel.measured_tread) {
    // The part of the tread that stands on the head, from the wheel's plane.
    const double lo = std::max(wheel.lateral_m - wheel.width_m / 2.0, -joint.half_width_m) - wheel.lateral_m;
    const double hi = std::min(wheel.lateral_m + wheel.width_m / 2.0, joint.half_width_m) - wheel.lateral_m;
    if (!(wheel.measured_tread->y_min_m() <= lo && hi <= wheel.measured_tread->y_max_m())) {
      throw InputError("wheel.profile", "the measured tread spans y = " + metres_text(wheel.measured_tread->y_min_m()) +
                                            " .. " + metres_text(wheel.measured_tread->y_max_m()) +
                                            " from the wheel's plane; the wheel stands on the head from " +
                                            metres_text(lo) + " to " + metres_text(hi));
    }
  }
  if (!(joint.dip_length_m > 0.0 && std::isfinite(joint.dip_length_m))) {
    throw InputError("joint.dip_length", "dip length must be a finite length > 0 m");
  }
  if (!(std::abs(wheel.conicity) < 1.0)) {
    throw InputError("wheel.conicity", "conicity must be in (-1, 1) (tan of the cone angle; 0.025 for 1:40)");
  }
  // The cone's radius at the edge of the tread that stands on the head.
  for (const double edge_y : {wheel.lateral_m - wheel.width_m / 2.0, wheel.lateral_m + wheel.width_m / 2.0}) {
    const double y = std::clamp(edge_y, -joint.half_width_m, joint.half_width_m);
    const double r = tread_radius_m(wheel, y);
    if (!(r > 0.5 * wheel.radius_m) && wheel.measured_tread) {
      throw InputError("wheel.profile", wheel.measured_tread->source() + ": the tread's radius at y = " +
                                            metres_text(y) + " is " + metres_text(r) +
                                            ", less than half its radius at the wheel's plane, " +
                                            metres_text(wheel.radius_m) + ": no tread a wheel stands on (a narrower wheel.width?)");
    }
    if (!(r > 0.5 * wheel.radius_m)) {
      throw InputError("wheel.conicity", "the cone's radius at y = " + metres_text(y) + " is " + metres_text(r) +
                                             ", less than half the rolling radius " + metres_text(wheel.radius_m) +
                                             ": a smaller conicity or a narrower wheel");
    }
  }
  if (joint.kind == JointKind::inclined) {
    // The inclined joint's step, as the step joint's u0 below: larger than R
    // it is a wall the wheel cannot climb (alpha would pass 90 deg).
    const double step_at_edge_m = std::abs(mismatch_height_m(joint, joint.half_width_m));
    if (!(step_at_edge_m < wheel.radius_m)) {
      throw InputError("joint.beta", "the step at the cut across the rail head, 2 tan(beta/2) b_t cot(theta) = " +
                                             metres_text(step_at_edge_m) + ", must be < wheel.radius = " +
                                             metres_text(wheel.radius_m) + " (a smaller beta or a larger theta)");
    }
  }
  if (joint.kind == JointKind::step && !(std::abs(joint.step_height_m) < wheel.radius_m)) {
    throw InputError("joint.step_height", "step height must satisfy |u0| < wheel.radius = " +
                                                  metres_text(wheel.radius_m) + ", got " + metres_text(joint.step_height_m));
  }
  check_joint_extent(joint, wheel, run_up_m);
}

bool is_level_joint(const JointParams& joint) {
  // The exact solve finds a corner contact to a slope of about sqrt(eps) =
  // 1.5e-8 (the circle's height is flat to round-off there): a dip whose
  // slopes are that small is noise (beta = 1e-8 gave exact/thesis = 1.17,
  // 2e-9 gave 7; from 5e-8 on they agree to 1e-6). A step keeps its jump
  // v sqrt(2 u0 / R) well above that down to 1e-9 m (checked to 1e-6 there).
  constexpr double kLevelDip_rad = 1e-7;
  constexpr double kLevelStep_m = 1e-9;
  return joint.kind == JointKind::step ? std::abs(joint.step_height_m) < kLevelStep_m
                                       : joint.beta_rad < kLevelDip_rad;
}

void check_joint_has_jump(const JointParams& joint) {
  if (!is_level_joint(joint)) return;
  if (joint.kind == JointKind::step) {
    throw InputError("joint.step_height",
                         "a step below 1e-9 m is level rail to double precision: there is no jump to simulate");
  }
  throw InputError("joint.beta", "a joint without a dip (beta below 1e-7 rad) is level rail to double precision: "
                                     "there is no jump to simulate");
}

}  // namespace railjoint
