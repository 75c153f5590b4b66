// `railjoint analytic`: the kinematic model alone. Never builds a Bullet world.

#include <iostream>
#include <memory>
#include <string>

#include "models/contact_points.h"
#include "models/time_history.h"
#include "scenes/cli/commands.h"
#include "scenes/cli/finite_number.h"
#include "scenes/cli/output_folder.h"
#include "scenes/cli/scene_command.h"
#include "scenes/report/json_values.h"
#include "scenes/report/prediction_csv.h"
#include "scenes/report/prediction_json.h"
#include "scenes/report/prediction_text.h"

namespace railjoint::cli {

namespace {

const SceneCommandHelp kHelp = {
    "analytic",
    "Kinematic model only (thesis ch. 3-4): contact scenario, transition value y_t, contact point A\n"
    "(x_A by the thesis's closed form and by an exact solve) and the vertical momentum jump in three\n"
    "forms: as printed in the thesis, exact with the horizontal speed held, small angle. A crowned\n"
    "head, a conical tread, a curved dip or a gap other slices carry the wheel over take the general\n"
    "model (the highest support over the wheel's slices): the exact jump only, and where on the head\n"
    "the wheel strikes (contact A's y).",
    "Scene file (TOML). Keys, SI units:\n"
    "  [joint] kind = \"inclined\"|\"step\", theta_deg (0, 90], beta [rad],\n"
    "          half_width b_t [m], length L [m], depth [m], gap [m],\n"
    "          step_height u0 [m] (< 0: step down),\n"
    "          crown_radius rho [m] (0 = flat): head top z = sqrt(rho^2 - y^2) - rho,\n"
    "          rail_profile = \"flat\"|\"crowned\"|\"60E1\"|\"head.csv\" (measured (y, z) [m]; a header\n"
    "          y_mm,z_mm reads mm), profile_tolerance [m] (its smoothing's RMS residual, 2e-6; 0 = none),\n"
    "          dip_shape = \"linear\"|\"quadratic\"|\"cosine\", dip_length D [m]: at s from the\n"
    "          joint along a rail end, t = tan(beta/2), the top is t s (linear); t s - t s^2/(2D)\n"
    "          up to D, then t D/2 (quadratic); (2 t D/pi) sin(pi s/(2D)) up to D, then\n"
    "          2 t D/pi (cosine); or dip_depth d [m] instead of beta, the depth below the level\n"
    "          (a straight edge's): beta = 2 atan(pi d/(2D)) cosine, 2 atan(2d/D) quadratic\n"
    "  [wheel] radius R [m], mass M [kg], width b_w [m] (0 = thin disc),\n"
    "          y lateral position y_w [m], speed v [m/s],\n"
    "          conicity kappa (0 = cylinder; 0.025 = 1:40): radius R - kappa (y - y_w),\n"
    "          profile = \"tread.csv\" (measured (y, r) [m], y from the wheel's plane; y_mm,r_mm: mm),\n"
    "          profile_tolerance [m] (as joint.profile_tolerance)",
    "wheel.y=0.01",
    {"joint", "wheel"}};

struct AnalyticOptions {
  bool json = false;
  std::string csv_path;
  std::string top_view_path;
  std::string head_section_path;
  int samples = 2001;
  double before_mm = 10.0;
  double after_mm = 12.0;
};

void run_analytic(const Scene& scene, const AnalyticOptions& options) {
  const ImpactPrediction& prediction = *scene.prediction;
  if (!options.csv_path.empty()) {
    check_time_history_range(scene, options.before_mm, options.after_mm);
    const double v = scene.wheel.speed_m_per_s;
    AtomicFile out = open_output_file(options.csv_path, "--csv", 12);
    write_time_history_csv(impact_time_history(scene.joint, scene.wheel, prediction, options.before_mm * 1e-3 / v,
                                               options.after_mm * 1e-3 / v, options.samples),
                           prediction, v, out);
    out.commit();
  }
  if (!options.top_view_path.empty()) {
    AtomicFile out = open_output_file(options.top_view_path, "--top-view", 12);
    write_top_view_csv(top_view_contacts(scene.joint, scene.wheel, 201), out);
    out.commit();
  }
  if (!options.head_section_path.empty()) {
    AtomicFile out = open_output_file(options.head_section_path, "--head-section", 12);
    write_head_section_csv(head_section(scene.joint, scene.wheel, 401), out);
    out.commit();
  }
  if (options.json) {
    nlohmann::json report = analytic_report_to_json(scene, prediction);
    report["profile_smoothing"] = profile_smoothing_json(scene.joint, scene.wheel, prediction);
    std::cout << report_text(report) << '\n';
  } else {
    print_prediction_summary(scene, prediction);
  }
}

void add_analytic_options(CLI::App& cmd, AnalyticOptions& options) {
  cmd.add_flag("--json", options.json, "Print one JSON object (SI units) instead of the summary");
  cmd.add_option("--csv", options.csv_path,
                 "Write the time histories (figs. 3.7 / 4.5: x, z, zdot, momentum, impulse; exact and linearised) as\n"
                 "CSV, t = 0 at the impact (scenes/report/outputs.md)");
  cmd.add_option("--top-view", options.top_view_path,
                 "Write the top view of contact points A, B and the wheel centre line over the rail head (fig. 4.8) as CSV");
  cmd.add_option("--head-section", options.head_section_path,
                 "Write the rail head and the resting wheel's tread across the track on plain rail (crown, cone: where\n"
                 "they touch) as CSV");
  cmd.add_option("--samples", options.samples, "Samples in the --csv time history")->check(CLI::Range(2, 10000000));
  // At most the longest rail a scene takes (joint.length <= 100 m); the
  // scene's own rails are checked when it is read.
  cmd.add_option("--before-mm", options.before_mm,
                 "Travel before the impact covered by --csv [mm]; the wheel must stay on the rails")
      ->check(finite_in(0.0, 1e5, "mm"));
  cmd.add_option("--after-mm", options.after_mm,
                 "Travel after the impact covered by --csv [mm]; the wheel must stay on the rails")
      ->check(finite_in(0.0, 1e5, "mm"));
}

}  // namespace

void add_analytic_command(CLI::App& app) {
  add_scene_command(app, kHelp, SceneCheck::model, add_analytic_options, run_analytic);
}

}  // namespace railjoint::cli
