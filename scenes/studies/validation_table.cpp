// The validation table (validation_table.h).

#include "scenes/studies/validation_table.h"

#include <cstdio>
#include <limits>

namespace railjoint {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string scenario_label(const ImpactPrediction& p, bool thin_disc_scene) {
  std::string label = p.scenario == ImpactScenario::step ? "step" : std::string("s") + to_string(p.scenario);
  // A thin disc is simulated as a narrow cylinder; its configuration is not the scene's.
  if (p.configuration && !thin_disc_scene) label += " c" + std::to_string(*p.configuration);
  if (p.on_landing) label += " landing";
  return label;
}

}  // namespace

const char* const kValidationHeader =
    // Aligned with validation_line's columns; the errors are relative, (sim - form) / form.
    "scene                   scenario        exact Ns   thesis Ns    small Ns      sim Ns   err exact  err thesis   err small  wall ms";

void write_validation_csv(const std::vector<ValidationRow>& rows, std::ostream& out) {
  out << "scene,scenario,governing_y_m,analytic_exact_Ns,analytic_thesis_Ns,analytic_small_angle_Ns,sim_Ns,"
         "sim_from_contacts_Ns,error_exact,error_thesis,error_small_angle,impact_x_predicted_m,impact_x_sim_m,"
         "max_penetration_m,liftoff,wall_ms,steps,pass\n";
  for (const auto& r : rows) {
    const ImpactPrediction& p = r.result.prediction();
    out << r.scene.name << ',' << scenario_label(p, r.scene.wheel.width_m == 0.0) << ',' << p.governing_y_m << ','
        << p.impulse.exact_Ns << ',' << p.impulse.thesis_Ns << ',' << p.impulse.small_angle_Ns << ','
        << r.result.impulse_Ns() << ',' << (r.result.impact ? r.result.impact->impulse_from_contacts_Ns() : kNaN) << ','
        << r.error.exact << ',' << r.error.thesis << ',' << r.error.small_angle << ',' << p.impact_wheel_x_m << ','
        << (r.result.impact ? r.result.impact->wheel_x_m() : kNaN) << ',' << r.result.max_penetration_m << ','
        << (r.result.liftoff_time_s().has_value() ? 1 : 0) << ',' << r.result.wall_seconds * 1e3 << ','
        << r.result.steps << ',' << (r.pass ? 1 : 0) << '\n';
  }
}

std::string validation_line(const ValidationRow& r, const char* separator) {
  const ImpactPrediction& p = r.result.prediction();
  char buffer[512];
  std::snprintf(buffer, sizeof buffer,
                "%-22s%s%-12s%s%10.3f%s%10.3f%s%10.3f%s%10.3f%s%+10.1e%s%+10.1e%s%+10.1e%s%7.1f%s%s",
                r.scene.name.c_str(), separator, scenario_label(p, r.scene.wheel.width_m == 0.0).c_str(), separator,
                p.impulse.exact_Ns, separator, p.impulse.thesis_Ns, separator, p.impulse.small_angle_Ns, separator,
                r.result.impulse_Ns(), separator, r.error.exact, separator, r.error.thesis, separator,
                r.error.small_angle, separator, r.result.wall_seconds * 1e3, separator,
                r.pass                ? "ok"
                : r.result.verdict.ok ? "FAIL"
                                      : "FAIL (suspect)");
  return buffer;
}

void write_validation_markdown(const std::vector<ValidationRow>& rows, std::ostream& out) {
  out << "| scene | scenario | exact [N s] | thesis [N s] | small angle [N s] | simulated [N s] | error vs exact "
         "| vs thesis | vs small angle | wall [ms] | within 1e-4 |\n";
  out << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const auto& r : rows) out << "| " << validation_line(r, " | ") << " |\n";
}

}  // namespace railjoint
