// `railjoint analytic`: the kinematic model alone. Never builds a Bullet world.

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "models/contact_points.h"
#include "models/impact_prediction.h"
#include "models/time_history.h"
#include "scenes/cli/commands.h"
#include "scenes/input_error.h"
#include "scenes/prediction_json.h"
#include "scenes/scene_file.h"
#include "scenes/studies/report_text.h"

namespace railjoint::cli {

namespace {

struct AnalyticOptions {
  std::string scene_path;
  std::vector<std::string> overrides;
  bool json = false;
  std::string csv_path;
  std::string top_view_path;
  int samples = 2001;
  double before_mm = 10.0;
  double after_mm = 12.0;
};

std::ofstream open_for_writing(const std::string& path, const std::string& flag) {
  std::ofstream out(path);
  if (!out) throw InputError(path, flag, "cannot write this file (does its folder exist?)");
  out.precision(12);
  return out;
}

void write_time_history(const Scene& scene, const AnalyticOptions& options) {
  const double v = scene.wheel.speed_m_per_s;
  const TimeHistory h = impact_time_history(scene.joint, scene.wheel, options.before_mm * 1e-3 / v,
                                            options.after_mm * 1e-3 / v, options.samples);
  std::ofstream out = open_for_writing(options.csv_path, "--csv");
  out << "t_s,z_exact_m,zdot_exact_m_per_s,z_linear_m,zdot_linear_m_per_s,momentum_exact_Ns,impulse_exact_Ns\n";
  for (std::size_t i = 0; i < h.time_s.size(); ++i) {
    out << h.time_s[i] << ',' << h.z_exact_m[i] << ',' << h.zdot_exact_m_per_s[i] << ',' << h.z_linear_m[i] << ','
        << h.zdot_linear_m_per_s[i] << ',' << h.momentum_exact_Ns[i] << ',' << h.impulse_exact_Ns[i] << '\n';
  }
}

void write_top_view(const Scene& scene, const AnalyticOptions& options) {
  std::ofstream out = open_for_writing(options.top_view_path, "--top-view");
  out << "y_m,cut_x_m,wheel_x_m,A_x_m,B_x_m,scenario,on_landing\n";
  for (const TopViewContact& row : top_view_contacts(scene.joint, scene.wheel, 201)) {
    out << row.y_m << ',' << row.cut_x_m << ',' << row.wheel_x_m << ',' << row.A_x_m << ',' << row.B_x_m << ','
        << to_string(row.scenario) << ',' << (row.on_landing ? 1 : 0) << '\n';
  }
}

void print_summary(const Scene& scene, const ImpactPrediction& p) {
  const JointParams& j = scene.joint;
  const WheelParams& w = scene.wheel;
  std::printf("scene  %s (%s)\n", scene.name.c_str(), scene.file.c_str());
  if (j.kind == JointKind::step) {
    std::printf("joint  step, u0 = %.3f mm (%s)\n", j.step_height_m * 1e3, j.step_height_m >= 0 ? "up" : "down");
  } else {
    std::printf("joint  inclined, theta = %.2f deg, beta = %.4f rad, b_t = %.1f mm, gap = %.1f mm\n",
                j.theta_rad * 180.0 / std::numbers::pi, j.beta_rad, j.half_width_m * 1e3, j.gap_m * 1e3);
  }
  std::printf("wheel  R = %.1f mm, M = %.1f kg, width = %.1f mm%s, y_w = %.3f mm, v = %.2f m/s\n", w.radius_m * 1e3,
              w.mass_kg, w.width_m * 1e3, w.width_m == 0.0 ? " (thin disc)" : "", w.lateral_m * 1e3,
              w.speed_m_per_s);
  if (p.scenario == ImpactScenario::step) {
    std::printf("contact  step %s: the wheel pivots about the edge %s\n", p.on_landing ? "down" : "up",
                p.on_landing ? "and lands (jump on landing)" : "");
  } else {
    std::printf("contact  scenario %s, y_t = %s, governing slice y = %.3f mm%s\n", to_string(p.scenario),
                std::isfinite(p.transition_y_m) ? (std::to_string(p.transition_y_m * 1e3) + " mm").c_str()
                                                : "inf (square joint)",
                p.governing_y_m * 1e3, p.on_landing ? ", step down: jump on landing" : "");
    if (p.configuration) {
      std::printf("         cylinder configuration %d (thesis fig. 3.21), line contact %.3f mm\n", *p.configuration,
                  p.line_contact_length_m * 1e3);
    }
  }
  std::printf("         x_A = %.4f mm (thesis closed form %s), alpha = %.4f mrad\n", p.x_A_m * 1e3,
              format_finite("%.4f mm", p.x_A_thesis_m * 1e3, "n/a: outside its range").c_str(), p.alpha_rad * 1e3);
  std::printf("         wheel centre at x = %.4f mm, A = (%.3f, %.3f, %.4f) mm, B = (%.3f, %.3f, %.4f) mm\n",
              p.impact_wheel_x_m * 1e3, p.contact_A_m.x() * 1e3, p.contact_A_m.y() * 1e3, p.contact_A_m.z() * 1e3,
              p.contact_B_m.x() * 1e3, p.contact_B_m.y() * 1e3, p.contact_B_m.z() * 1e3);
  std::printf("         zdot: %.5f m/s -> %.5f m/s\n", p.zdot_before_m_per_s, p.zdot_after_m_per_s);
  const double exact = p.impulse.exact_Ns;
  // Against no jump (a level joint) a relative difference means nothing.
  const auto vs_exact = [exact](double form) {
    return exact == 0.0 ? std::string("level joint: no jump")
                        : format_finite("%+.4f %% vs exact", 100.0 * (form - exact) / exact);
  };
  const auto form_text = [](double form) { return format_finite("%12.4f N s", form, "         n/a    "); };
  std::printf("vertical momentum jump Delta p_z\n");
  std::printf("  exact, v held       %s\n", form_text(exact).c_str());
  std::printf("  thesis as printed   %s  (%s)\n", form_text(p.impulse.thesis_Ns).c_str(),
              std::isfinite(p.impulse.thesis_Ns) ? vs_exact(p.impulse.thesis_Ns).c_str()
                                                 : "the printed form has no real value here");
  std::printf("  small angle         %s  (%s)\n", form_text(p.impulse.small_angle_Ns).c_str(),
              vs_exact(p.impulse.small_angle_Ns).c_str());
}

}  // namespace

void add_analytic_command(CLI::App& app) {
  auto options = std::make_shared<AnalyticOptions>();
  CLI::App* cmd = app.add_subcommand(
      "analytic",
      "Kinematic model only (thesis ch. 3-4): contact scenario, transition value y_t, contact point A\n"
      "(x_A by the thesis's closed form and by an exact solve) and the vertical momentum jump in three\n"
      "forms: as printed in the thesis, exact with the horizontal speed held, small angle.");
  cmd->add_option("scene", options->scene_path, "Scene file (TOML). Keys, SI units:\n"
                                                "  [joint] kind = \"inclined\"|\"step\", theta_deg (0, 90], beta [rad],\n"
                                                "          half_width b_t [m], length L [m], depth [m], gap [m],\n"
                                                "          step_height u0 [m] (< 0: step down)\n"
                                                "  [wheel] radius R [m], mass M [kg], width b_w [m] (0 = thin disc),\n"
                                                "          y lateral position y_w [m], speed v [m/s]")
      ->required();
  cmd->add_option("--set", options->overrides, "Override a scene key: section.key=value (repeatable), e.g. wheel.y=0.01");
  cmd->add_flag("--json", options->json, "Print one JSON object (SI units) instead of the summary");
  cmd->add_option("--csv", options->csv_path,
                  "Write the time histories (figs. 3.7 / 4.5: z, zdot, momentum, impulse; exact and linearised) as CSV");
  cmd->add_option("--top-view", options->top_view_path,
                  "Write the top view of contact points A, B and the wheel centre line over the rail head (fig. 4.8) as CSV");
  cmd->add_option("--samples", options->samples, "Samples in the --csv time history")->check(CLI::Range(2, 10000000));
  cmd->add_option("--before-mm", options->before_mm, "Travel before the impact covered by --csv [mm]")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--after-mm", options->after_mm, "Travel after the impact covered by --csv [mm]")
      ->check(CLI::NonNegativeNumber);
  cmd->callback([options] {
    const Scene scene = load_scene(options->scene_path, options->overrides);
    const ImpactPrediction prediction = predict_impact(scene.joint, scene.wheel);
    if (!options->csv_path.empty()) write_time_history(scene, *options);
    if (!options->top_view_path.empty()) write_top_view(scene, *options);
    if (options->json) {
      std::cout << prediction_to_json(prediction).dump(2) << '\n';
    } else {
      print_summary(scene, prediction);
    }
  });
}

}  // namespace railjoint::cli
