#pragma once
// Joints the geometry tests run over, and the expected geometry written out
// again from models/DESIGN.md "Coordinates and symbols" and the thesis (sections 3.2.2, 3.3), independently of
// geometry/: x along travel, V bottom of the dip at x = 0, cut x = y cot(theta),
// each rail end set back by g / (2 sin theta) along x for a gap g normal to the cut.

#include <cmath>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "models/parameters.h"

namespace railjoint::test {

struct JointCase {
  std::string name;
  JointParams joint;
};

inline std::ostream& operator<<(std::ostream& out, const JointCase& c) { return out << c.name; }

inline double degrees(double deg) { return deg * std::numbers::pi / 180.0; }

inline std::vector<JointCase> joint_cases() {
  std::vector<JointCase> cases;
  JointParams thesis;  // fig. 4.5: theta 30 deg, beta 0.03, b_t 20 mm, L 1 m, depth 50 mm
  cases.push_back({"thesis_30deg", thesis});

  JointParams square = thesis;
  square.theta_rad = std::numbers::pi / 2.0;
  cases.push_back({"square_90deg", square});

  // 1 deg: the cut runs b_t cot(1 deg) = 1.146 m either side of x = 0.
  JointParams shallow = thesis;
  shallow.theta_rad = degrees(1.0);
  shallow.length_m = 3.0;
  cases.push_back({"shallow_1deg", shallow});

  JointParams flat = thesis;
  flat.beta_rad = 0.0;
  cases.push_back({"flat_beta0", flat});

  JointParams gap = thesis;
  gap.gap_m = 0.005;
  cases.push_back({"gap_5mm", gap});

  JointParams steep_gap = thesis;
  steep_gap.theta_rad = degrees(60.0);
  steep_gap.beta_rad = 0.05;
  steep_gap.gap_m = 0.002;
  steep_gap.half_width_m = 0.035;
  steep_gap.length_m = 1.3;
  steep_gap.depth_m = 0.08;
  cases.push_back({"theta60_gap2mm_wide", steep_gap});

  JointParams step_up = thesis;
  step_up.kind = JointKind::step;
  step_up.step_height_m = 0.001;
  cases.push_back({"step_up_1mm", step_up});

  JointParams step_down = step_up;
  step_down.step_height_m = -0.002;
  step_down.gap_m = 0.003;
  cases.push_back({"step_down_2mm_gap3mm", step_down});
  return cases;
}

inline bool is_step(const JointParams& j) { return j.kind == JointKind::step; }
inline double cot_theta(const JointParams& j) {
  return is_step(j) || j.theta_rad == std::numbers::pi / 2.0 ? 0.0 : 1.0 / std::tan(j.theta_rad);
}
inline double half_gap_along_x(const JointParams& j) {
  return is_step(j) ? j.gap_m / 2.0 : j.gap_m / (2.0 * std::sin(j.theta_rad));
}
inline double tan_half_beta(const JointParams& j) { return is_step(j) ? 0.0 : std::tan(j.beta_rad / 2.0); }

/// x of rail `rail`'s cut face at lateral y.
inline double expected_cut_x(const JointParams& j, double y, int rail) {
  return y * cot_theta(j) + (rail == 0 ? -1.0 : 1.0) * half_gap_along_x(j);
}

/// Rail top of rail `rail` at x: -tan(beta/2) x incoming, +tan(beta/2) x outgoing;
/// step joint 0 and u0.
inline double expected_top(const JointParams& j, int rail, double x) {
  if (is_step(j)) return rail == 0 ? 0.0 : j.step_height_m;
  return (rail == 0 ? -1.0 : 1.0) * tan_half_beta(j) * x;
}

/// Volume of one rail end: the integral over its footprint of (top + depth).
/// Inclined, incoming rail, with k = cot(theta), s = the gap's shift along x,
/// c(y) = y k - s, t = tan(beta/2):
///   int_{-L/2}^{c} (d - t x) dx = d (c + L/2) - t/2 (c^2 - L^2/4);
///   int_{-b}^{b} c dy = -2 b s,  int_{-b}^{b} c^2 dy = 2 b^3 k^2 / 3 + 2 b s^2;
///   V_in = 2 b [d (L/2 - s) + t (L^2/8 - s^2/2 - b^2 k^2 / 6)].
/// The outgoing rail is the incoming one turned by 180 deg about z
/// ((x, y) -> (-x, -y) maps the cut line and the tops onto each other): same V.
/// Step joint: 2 b (L/2 - s) d incoming, 2 b (L/2 - s)(d + u0) outgoing.
inline double expected_volume(const JointParams& j, int rail) {
  const double b = j.half_width_m, d = j.depth_m, L = j.length_m;
  const double s = half_gap_along_x(j), k = cot_theta(j), t = tan_half_beta(j);
  if (is_step(j)) return 2.0 * b * (L / 2.0 - s) * (d + (rail == 0 ? 0.0 : j.step_height_m));
  return 2.0 * b * (d * (L / 2.0 - s) + t * (L * L / 8.0 - s * s / 2.0 - b * b * k * k / 6.0));
}

}  // namespace railjoint::test
