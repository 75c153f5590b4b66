// The text summary of `railjoint analytic` (prediction_text.h).

#include "scenes/report/prediction_text.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>

#include "models/dip_profile.h"
#include "models/jump_error.h"
#include "models/profile_curve.h"
#include "models/profile_sensitivity.h"
#include "scenes/report/prediction_json.h"
#include "scenes/report/report_text.h"

namespace railjoint {

namespace {
// A measured profile's file and what the smoothing did to its points.
void print_measured_profile(const char* what, const ProfileCurve& curve) {
  print_text("       measured %s %s, %zu points, ", what, curve.source().c_str(), curve.point_count());
  const ProfileSmoothing& s = curve.smoothing();
  if (s.tolerance_m == 0.0) {
    print_text("interpolated through them (profile_tolerance 0)\n");
  } else {
    print_text("smoothed to %.2f um RMS: residual RMS %.2f um, max %.2f um\n", s.tolerance_m * 1e6,
               s.rms_residual_m * 1e6, s.max_residual_m * 1e6);
  }
  if (s.point_scatter_m) {
    const bool beyond = s.tolerance_m > 0.0 && *s.point_scatter_m > s.tolerance_m;
    print_text("         its points scatter about %.2f um RMS about a smooth curve%s\n", *s.point_scatter_m * 1e6,
               beyond ? "; WARNING: more than the tolerance, which the smoothing leaves in: the jump may be the "
                        "scatter's (give profile_tolerance about that)"
                      : "");
  }
}
}  // namespace

void print_prediction_summary(const Scene& scene, const ImpactPrediction& p) {
  const JointParams& j = scene.joint;
  const WheelParams& w = scene.wheel;
  print_text("scene  %s (%s)\n", scene.name.c_str(), scene.file.c_str());
  if (j.kind == JointKind::step) {
    print_text("joint  step, u0 = %.3f mm (%s)\n", j.step_height_m * 1e3, j.step_height_m >= 0 ? "up" : "down");
  } else {
    print_text("joint  inclined, theta = %.2f deg, beta = %.4f rad, b_t = %.1f mm, gap = %.1f mm\n",
               j.theta_rad * 180.0 / std::numbers::pi, j.beta_rad, j.half_width_m * 1e3, j.gap_m * 1e3);
    if (j.dip_shape != DipShape::linear) {
      // The depth a straight edge measures, and how beta follows from it (models/dip_profile.h).
      print_text("       dip %s over %.1f mm each side (%.1f mm overall), %.4f mm deep: beta = 2 atan(%s) = %.6f rad\n",
                 to_string(j.dip_shape), j.dip_length_m * 1e3, 2.0 * j.dip_length_m * 1e3,
                 dip_depth_m(j.dip_shape, j.beta_rad, j.dip_length_m) * 1e3,
                 j.dip_shape == DipShape::cosine ? "pi d / (2 D)" : "2 d / D", j.beta_rad);
    }
  }
  if (j.rail_profile == RailProfile::en_60e1) print_text("       60E1 head (300, 80, 13 mm radii)\n");
  if (j.crown_radius_m > 0.0) print_text("       crowned head, radius %.1f mm\n", j.crown_radius_m * 1e3);
  if (j.measured_head) print_measured_profile("head", *j.measured_head);
  print_text("wheel  R = %.1f mm, M = %.1f kg, width = %.1f mm%s, y_w = %.3f mm, v = %.2f m/s\n", w.radius_m * 1e3,
             w.mass_kg, w.width_m * 1e3, w.width_m == 0.0 ? " (thin disc)" : "", w.lateral_m * 1e3,
             w.speed_m_per_s);
  if (w.conicity != 0.0) {
    print_text("       conical tread, conicity %.4f (1:%.1f, radius larger towards %sy)\n", w.conicity,
               1.0 / std::abs(w.conicity), w.conicity > 0.0 ? "-" : "+");
  }
  if (w.measured_tread) print_measured_profile("tread", *w.measured_tread);
  if (p.scenario == ImpactScenario::step) {
    print_text("contact  step %s: the wheel pivots about the edge %s\n", p.on_landing ? "down" : "up",
               p.on_landing ? "and lands (jump on landing)" : "");
  } else {
    print_text("contact  scenario %s, y_t = %s, governing slice y = %.3f mm%s\n", to_string(p.scenario),
               std::isfinite(p.transition_y_m) ? (std::to_string(p.transition_y_m * 1e3) + " mm").c_str()
               : std::isnan(p.transition_y_m)  ? "n/a (not the thesis's geometry)"
                                               : "inf (square joint)",
               p.governing_y_m * 1e3, p.on_landing ? ", step down: jump on landing" : "");
    if (p.configuration) {
      print_text("         cylinder configuration %d (thesis fig. 3.21), line contact %.3f mm\n", *p.configuration,
                 p.line_contact_length_m * 1e3);
    }
  }
  print_text("         x_A = %.4f mm (thesis closed form %s), alpha = %.4f mrad\n", p.x_A_m * 1e3,
             format_finite("%.4f mm", p.x_A_thesis_m * 1e3, "n/a: outside its range").c_str(), p.alpha_rad * 1e3);
  print_text("         wheel centre at x = %.4f mm, A = (%.3f, %.3f, %.4f) mm, B = (%.3f, %.3f, %.4f) mm\n",
             p.impact_wheel_x_m * 1e3, p.contact_A_m.x() * 1e3, p.contact_A_m.y() * 1e3, p.contact_A_m.z() * 1e3,
             p.contact_B_m.x() * 1e3, p.contact_B_m.y() * 1e3, p.contact_B_m.z() * 1e3);
  print_text("         zdot: %.5f m/s -> %.5f m/s\n", p.zdot_before_m_per_s, p.zdot_after_m_per_s);
  const double exact = p.impulse.exact_Ns;
  // Against no jump (a level joint) a relative difference means nothing.
  const auto vs_exact = [exact](double form) {
    return exact == 0.0 ? std::string("level joint: no jump")
                        : format_finite("%+.4f %% vs exact", 100.0 * relative_error(form, exact));
  };
  const auto form_text = [](double form) { return format_finite("%12.4f N s", form, "         n/a    "); };
  print_text("vertical momentum jump Delta p_z\n");
  print_text("  exact, v held       %s\n", form_text(exact).c_str());
  // The general model (crown, cone, curved dip, a gap the slice rule does
  // not cover) leaves both of the thesis's forms out.
  const bool thesis_forms = std::isfinite(p.impulse.small_angle_Ns);
  const char* no_form = thesis_forms ? "the printed form has no real value here"
                                     : "the thesis's forms hold for its own geometry only";
  print_text("  thesis as printed   %s  (%s)\n", form_text(p.impulse.thesis_Ns).c_str(),
             std::isfinite(p.impulse.thesis_Ns) ? vs_exact(p.impulse.thesis_Ns).c_str() : no_form);
  print_text("  small angle         %s  (%s)\n", form_text(p.impulse.small_angle_Ns).c_str(),
             thesis_forms ? vs_exact(p.impulse.small_angle_Ns).c_str() : no_form);
  if (const std::optional<ProfileSensitivity> s = profile_sensitivity(j, w, exact)) {
    if (s->unsmoothed_error.empty()) {
      print_text("  through the points  %s  (the smoothing changes the jump by %+.2f %%%s)\n",
                 form_text(s->jump_unsmoothed_Ns).c_str(), 100.0 * s->relative_change,
                 !(std::abs(s->relative_change) <= 0.01)
                     ? "; WARNING: over 1 %, the points' noise decides the jump without it"
                     : "");
    } else {
      print_text("  through the points         n/a      (WARNING: without the smoothing: %s)\n",
                 s->unsmoothed_error.c_str());
    }
  }
  if (const std::optional<SquareJointReference> square = square_joint_reference(j, w, p)) {
    print_text("  square joint        %s  (theta = 90 deg, all else as here: this joint's exact jump is %.4fx it)\n",
               form_text(square->exact_Ns).c_str(), square->ratio);
  }
}

}  // namespace railjoint
