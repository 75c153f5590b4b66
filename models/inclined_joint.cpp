#include "models/inclined_joint.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace railjoint {

bool is_square_joint(double theta_rad) { return std::abs(theta_rad - std::numbers::pi / 2.0) < 1e-12; }

namespace {
// cos and sin of theta, remembered for the last theta: the narrow phase asks
// where the cut is some thirty times a force run's step with the same joint,
// and libm's sin and cos were a tenth of a 60E1 force run.
struct CutTrig {
  double theta_rad = std::numbers::pi / 2.0;
  double cos = std::cos(std::numbers::pi / 2.0);
  double sin = 1.0;
};
const CutTrig& cut_trig(double theta_rad) {
  thread_local CutTrig last;
  if (theta_rad != last.theta_rad) last = {theta_rad, std::cos(theta_rad), std::sin(theta_rad)};
  return last;
}
}  // namespace

double cut_x_m(double theta_rad, double y_m) {
  if (is_square_joint(theta_rad)) return 0.0;
  const CutTrig& trig = cut_trig(theta_rad);
  return y_m * trig.cos / trig.sin;  // the order of the operations as before: the same bits
}

double gap_half_shift_m(const JointParams& joint) {
  if (joint.kind == JointKind::step) return joint.gap_m / 2.0;
  // No gap: no shift, without a sine (0 / (2 sin theta) for every theta).
  return joint.gap_m == 0.0 ? 0.0 : joint.gap_m / (2.0 * cut_trig(joint.theta_rad).sin);
}

double mismatch_height_m(const JointParams& joint, double y_m) {
  return 2.0 * std::tan(joint.beta_rad / 2.0) * cut_x_m(joint.theta_rad, y_m);
}

double transition_y_m(const JointParams& joint, double radius_m) {
  if (is_square_joint(joint.theta_rad)) return std::numeric_limits<double>::infinity();
  return radius_m * std::sin(joint.beta_rad / 2.0) * std::tan(joint.theta_rad);
}

double x_A_exact_m(const JointParams& joint, double radius_m, double y_m) {
  const double R = radius_m;
  const double y = std::abs(y_m);
  if (y <= transition_y_m(joint, R)) return R * std::sin(joint.beta_rad / 2.0);
  // Centre at (x_w, -t x_w + R / cos(beta/2)) on the offset line of the incoming
  // top z = -t x; corner at (x_c, t x_c). With d = x_c - x_w and
  // k = R / cos(beta/2) - 2 t x_c the height difference is h = k + t d, and
  // d^2 + h^2 = R^2 gives (1 + t^2) d^2 + 2 k t d + k^2 - R^2 = 0. The first
  // contact as the wheel advances (d decreasing) is the larger root.
  const double t = std::tan(joint.beta_rad / 2.0);
  const double x_c = cut_x_m(joint.theta_rad, y);
  const double k = R / std::cos(joint.beta_rad / 2.0) - 2.0 * t * x_c;
  const double one_plus_t2 = 1.0 + t * t;
  return (-k * t + std::sqrt(one_plus_t2 * R * R - k * k)) / one_plus_t2;
}

double x_A_thesis_m(const JointParams& joint, double radius_m, double y_m) {
  const double R = radius_m;
  const double y = std::abs(y_m);
  const double y_t = transition_y_m(joint, R);
  const double s = std::sin(joint.beta_rad / 2.0);
  if (y <= y_t) return R * s;
  // Appendix C, functions a(), x_cutoff_loc() and get_xA(), transcribed term by term.
  const double c = std::cos(joint.beta_rad / 2.0);
  const double T = std::tan(joint.theta_rad);
  const double yl = y - y_t;  // local y' = y - y_t
  const double root = std::sqrt(T * T * s * s * c * c * R * R + 2.0 * T * T * s * s * c * R * R + T * T * s * s * R * R +
                                4.0 * T * s * c * c * R * yl + 4.0 * c * s * R * yl * T - 4.0 * s * R * yl * T +
                                4.0 * c * c * yl * yl - 4.0 * yl * yl);
  const double a = (-T * s * c * R - T * s * R - c * c * yl + root) / ((c * c - 2.0) * T);
  const double x_joint_local = yl / T + R * s;
  return x_joint_local - a;
}

}  // namespace railjoint
