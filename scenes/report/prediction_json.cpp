#include "scenes/report/prediction_json.h"

#include <numbers>

#include "models/profile_curve.h"
#include "models/profile_sensitivity.h"
#include "scenes/report/json_values.h"
#include "scenes/report/scene_json.h"
#include "support/input_error.h"

namespace railjoint {

nlohmann::json prediction_to_json(const ImpactPrediction& p) {
  nlohmann::json j;
  if (p.scenario == ImpactScenario::step) {
    j["scenario"] = "step";
  } else {
    j["scenario"] = p.scenario == ImpactScenario::one ? 1 : 2;
  }
  j["on_landing"] = p.on_landing;
  j["y_t_m"] = finite_or_null(p.transition_y_m);
  j["governing_y_m"] = p.governing_y_m;
  j["configuration"] = or_null(p.configuration);
  j["line_contact_length_m"] = p.line_contact_length_m;
  j["x_A_m"] = p.x_A_m;
  j["x_A_thesis_m"] = finite_or_null(p.x_A_thesis_m);
  j["alpha_rad"] = p.alpha_rad;
  j["alpha_thesis_rad"] = finite_or_null(p.alpha_thesis_rad);
  j["impact_x_m"] = p.impact_wheel_x_m;
  j["impact_z_m"] = p.impact_wheel_z_m;
  j["contact_A_m"] = point_json(p.contact_A_m);
  j["contact_B_m"] = point_json(p.contact_B_m);
  j["zdot_before_m_per_s"] = p.zdot_before_m_per_s;
  j["zdot_after_m_per_s"] = p.zdot_after_m_per_s;
  // As a sweep's analytic.exact_Ns, analytic.thesis_Ns, analytic.small_angle_Ns.
  j["exact_Ns"] = p.impulse.exact_Ns;
  j["thesis_Ns"] = finite_or_null(p.impulse.thesis_Ns);
  j["small_angle_Ns"] = finite_or_null(p.impulse.small_angle_Ns);
  return j;
}

std::optional<SquareJointReference> square_joint_reference(const JointParams& joint, const WheelParams& wheel,
                                                           const ImpactPrediction& prediction) {
  if (joint.kind != JointKind::inclined) return std::nullopt;
  JointParams square = joint;
  square.theta_rad = std::numbers::pi / 2.0;
  double square_Ns = 0.0;
  try {
    square_Ns = predict_impact(square, wheel).impulse.exact_Ns;
  } catch (const InputError&) {
    return std::nullopt;  // no crossing over the square cut
  }
  if (square_Ns == 0.0) return std::nullopt;
  return SquareJointReference{square_Ns, prediction.impulse.exact_Ns / square_Ns};
}

nlohmann::json analytic_block_to_json(const JointParams& joint, const WheelParams& wheel,
                                      const ImpactPrediction& prediction) {
  nlohmann::json block = prediction_to_json(prediction);
  const std::optional<SquareJointReference> square = square_joint_reference(joint, wheel, prediction);
  block["square_joint_exact_Ns"] = square ? nlohmann::json(square->exact_Ns) : nlohmann::json(nullptr);
  block["relative_to_square_joint"] = square ? nlohmann::json(square->ratio) : nlohmann::json(nullptr);
  return block;
}

nlohmann::json analytic_report_to_json(const Scene& scene, const ImpactPrediction& prediction) {
  nlohmann::json report = analytic_block_to_json(scene.joint, scene.wheel, prediction);
  report["scene"] = scene_json(scene);
  return report;
}

namespace {
nlohmann::json curve_json(const ProfileCurve& curve) {
  nlohmann::json j;
  j["file"] = curve.source();
  j["points"] = curve.point_count();
  j["tolerance_m"] = curve.smoothing().tolerance_m;
  j["rms_residual_m"] = curve.smoothing().rms_residual_m;
  j["max_residual_m"] = curve.smoothing().max_residual_m;
  const std::optional<double> scatter = curve.smoothing().point_scatter_m;
  j["point_scatter_m"] = or_null(scatter);
  return j;
}
}  // namespace

nlohmann::json profile_smoothing_json(const JointParams& joint, const WheelParams& wheel,
                                      const ImpactPrediction& prediction) {
  const std::optional<ProfileSensitivity> s = profile_sensitivity(joint, wheel, prediction.impulse.exact_Ns);
  if (!s) return nullptr;
  nlohmann::json j;
  j["head"] = joint.measured_head ? curve_json(*joint.measured_head) : nlohmann::json(nullptr);
  j["tread"] = wheel.measured_tread ? curve_json(*wheel.measured_tread) : nlohmann::json(nullptr);
  j["jump_Ns"] = s->jump_Ns;
  j["jump_unsmoothed_Ns"] = finite_or_null(s->jump_unsmoothed_Ns);
  j["relative_change"] = finite_or_null(s->relative_change);
  j["unsmoothed_error"] = s->unsmoothed_error.empty() ? nlohmann::json(nullptr) : nlohmann::json(s->unsmoothed_error);
  j["scatter_beyond_tolerance"] = s->scatter_beyond_tolerance;
  j["sensitive"] = s->sensitive;
  return j;
}

}  // namespace railjoint
