#include "scenes/report/prediction_json.h"

#include "scenes/report/json_values.h"

namespace railjoint {

nlohmann::json prediction_to_json(const ImpactPrediction& p) {
  nlohmann::json j;
  if (p.scenario == ImpactScenario::step) {
    j["scenario"] = "step";
  } else {
    j["scenario"] = p.scenario == ImpactScenario::one ? 1 : 2;
  }
  j["units"] = "SI: m, s, rad, N s";
  j["on_landing"] = p.on_landing;
  j["y_t"] = finite_or_null(p.transition_y_m);
  j["governing_y"] = p.governing_y_m;
  j["configuration"] = p.configuration ? nlohmann::json(*p.configuration) : nlohmann::json(nullptr);
  j["line_contact_length"] = p.line_contact_length_m;
  j["x_A"] = p.x_A_m;
  j["x_A_thesis"] = finite_or_null(p.x_A_thesis_m);
  j["alpha"] = p.alpha_rad;
  j["alpha_thesis"] = finite_or_null(p.alpha_thesis_rad);
  j["impact_x"] = p.impact_wheel_x_m;
  j["impact_z"] = p.impact_wheel_z_m;
  j["contact_A"] = point_json(p.contact_A_m);
  j["contact_B"] = point_json(p.contact_B_m);
  j["zdot_before"] = p.zdot_before_m_per_s;
  j["zdot_after"] = p.zdot_after_m_per_s;
  j["impulse"] = {{"exact", p.impulse.exact_Ns},
                  {"thesis", finite_or_null(p.impulse.thesis_Ns)},
                  {"small_angle", p.impulse.small_angle_Ns}};
  return j;
}

}  // namespace railjoint
