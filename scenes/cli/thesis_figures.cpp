// The data behind the thesis's figures redrawn by `railjoint validate`
// (thesis_figures.h). Simulated points always use the wheel as simulated (a
// thin disc is a 1 mm wide cylinder) and are compared with that wheel's
// analytic values; thin-disc curves are written beside them.

#include "scenes/cli/thesis_figures.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "models/impact_prediction.h"
#include "models/time_history.h"
#include "scenes/cli/output_folder.h"
#include "sim/setting_checks.h"

namespace railjoint::cli {

namespace {

namespace fs = std::filesystem;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

double relative(double measured, double reference) { return (measured - reference) / reference; }

std::ofstream open_csv(const fs::path& dir, const std::string& name) { return open_output_file(dir / name, "--out"); }

// Fig. 3.7's step: u0 = 0.3 m under a wheel of R = 1 m (u0 / R = 0.3: the
// three forms of the jump differ by +20 % and -24 % there). 2 m of rail hold
// the approach of such a wheel (check_joint_geometry needs 1.77 m).
constexpr const char* kFigure37Scene = R"(
[joint]
kind = "step"
step_height = 0.3
length = 2.0
[wheel]
radius = 1.0
mass = 750.0
speed = 50.0
)";

}  // namespace

void write_figure_3_7_data(const Scene& base, const fs::path& dir) {
  const Scene scene = parse_scene(kFigure37Scene, "figure 3.7 scene");
  const SimulationResult result = simulate_crossing(scene.joint, scene.wheel, base.sim);
  const ImpactPrediction& p = result.prediction;
  const double v = scene.wheel.speed_m_per_s;
  const double M = scene.wheel.mass_kg;

  // t = 0 at the predicted two-point contact, z relative to the centre there.
  std::ofstream sim = open_csv(dir, "fig3_7_sim.csv");
  sim << "t_s,z_m,zdot_m_per_s,momentum_Ns\n";
  for (const WheelSample& s : result.trajectory.samples) {
    sim << (s.centre_m.x() - p.impact_wheel_x_m) / v << ',' << s.centre_m.z() - p.impact_wheel_z_m << ','
        << s.velocity_m_per_s.z() << ',' << M * s.velocity_m_per_s.z() << '\n';
  }
  // From 2 ms before the contact until the centre is over the edge (the end
  // of the kinematic pivot): 14.3 ms at 50 m/s.
  const TimeHistory h = impact_time_history(scene.joint, scene.wheel, 2e-3, -p.impact_wheel_x_m / v, 2001);
  std::ofstream analytic = open_csv(dir, "fig3_7_analytic.csv");
  analytic << "t_s,z_exact_m,zdot_exact_m_per_s,z_linear_m,zdot_linear_m_per_s,momentum_exact_Ns,impulse_exact_Ns\n";
  for (std::size_t i = 0; i < h.time_s.size(); ++i) {
    analytic << h.time_s[i] << ',' << h.z_exact_m[i] << ',' << h.zdot_exact_m_per_s[i] << ',' << h.z_linear_m[i] << ','
             << h.zdot_linear_m_per_s[i] << ',' << h.momentum_exact_Ns[i] << ',' << h.impulse_exact_Ns[i] << '\n';
  }
  std::ofstream jump = open_csv(dir, "fig3_7_jump.csv");
  jump << "form,jump_Ns,time_s\n";
  jump << "exact," << p.impulse.exact_Ns << ",0\n";
  jump << "thesis," << p.impulse.thesis_Ns << ",0\n";
  jump << "small_angle," << p.impulse.small_angle_Ns << ",0\n";
  jump << "simulated," << result.impulse_Ns << ',' << (result.impact_x_m - p.impact_wheel_x_m) / v << '\n';
}

void write_figure_4_3_data(const Scene& base, const fs::path& dir) {
  std::ofstream out = open_csv(dir, "fig4_3_analytic.csv");
  out << "theta_deg,beta_rad,y_t_m\n";
  for (double theta_deg : {30.0, 45.0, 60.0}) {
    JointParams joint = base.joint;
    joint.theta_rad = radians(theta_deg);
    for (int i = 0; i <= 100; ++i) {
      joint.beta_rad = 0.05 * i / 100.0;
      out << theta_deg << ',' << joint.beta_rad << ',' << predict_impact(joint, base.wheel).transition_y_m << '\n';
    }
  }
}

void write_figure_4_5_data(const Scene& scene, const SimulationResult& result, const fs::path& dir) {
  const ImpactPrediction& p = result.prediction;
  const double v = result.simulated_wheel.speed_m_per_s;
  const double z_bottom = result.simulated_wheel.radius_m / std::cos(scene.joint.beta_rad / 2.0);
  std::ofstream sim = open_csv(dir, scene.name + "_sim.csv");
  sim << "t_s,z_m,zdot_m_per_s,momentum_Ns\n";
  const double mass = result.simulated_wheel.mass_kg;
  for (const WheelSample& s : result.trajectory.samples) {
    sim << s.centre_m.x() / v << ',' << s.centre_m.z() - z_bottom << ',' << s.velocity_m_per_s.z() << ','
        << mass * s.velocity_m_per_s.z() << '\n';
  }
  const double travel_before_m = 0.010 + std::max(0.0, p.impact_wheel_x_m);
  const double travel_after_m = 0.012 - std::max(0.0, p.impact_wheel_x_m);
  const TimeHistory h = impact_time_history(scene.joint, result.simulated_wheel, travel_before_m / v,
                                            std::max(travel_after_m, 0.002) / v, 2001);
  std::ofstream analytic = open_csv(dir, scene.name + "_analytic.csv");
  analytic << "t_s,z_exact_m,zdot_exact_m_per_s,z_linear_m,zdot_linear_m_per_s,momentum_exact_Ns\n";
  const double t_impact = p.impact_wheel_x_m / v;
  const double z_impact = p.impact_wheel_z_m - z_bottom;
  for (std::size_t i = 0; i < h.time_s.size(); ++i) {
    analytic << h.time_s[i] + t_impact << ',' << h.z_exact_m[i] + z_impact << ',' << h.zdot_exact_m_per_s[i] << ','
             << h.z_linear_m[i] + z_impact << ',' << h.zdot_linear_m_per_s[i] << ',' << h.momentum_exact_Ns[i] << '\n';
  }
}

// The simulated "disc" has a small width whose inner face governs, so the
// simulated points are compared with the exact curve of that wheel; the
// thin-disc curves (exact and as printed) are drawn beside it.
void write_figure_4_6_data(const Scene& base, const fs::path& dir) {
  std::ofstream curves = open_csv(dir, "fig4_6_analytic.csv");
  std::ofstream points = open_csv(dir, "fig4_6_sim.csv");
  curves << "theta_deg,beta_rad,exact_simulated_wheel_Ns,exact_thin_disc_Ns,thesis_thin_disc_Ns,scenario\n";
  points << "theta_deg,beta_rad,sim_Ns,exact_Ns,error_exact\n";
  for (double theta_deg : {30.0, 45.0, 60.0}) {
    JointParams joint = base.joint;
    joint.theta_rad = radians(theta_deg);
    WheelParams disc = base.wheel;
    disc.lateral_m = 0.015;
    disc.width_m = 0.0;
    const WheelParams simulated = wheel_as_simulated(disc, base.sim);
    for (int i = 0; i <= 100; ++i) {
      joint.beta_rad = 0.0005 + 0.0495 * i / 100.0;
      const ImpactPrediction thin = predict_impact(joint, disc);
      curves << theta_deg << ',' << joint.beta_rad << ',' << predict_impact(joint, simulated).impulse.exact_Ns << ','
             << thin.impulse.exact_Ns << ',' << thin.impulse.thesis_Ns << ',' << to_string(thin.scenario) << '\n';
    }
    for (double beta : {0.01, 0.02, 0.03, 0.04, 0.05}) {
      joint.beta_rad = beta;
      const SimulationResult result = simulate_crossing(joint, disc, base.sim);
      points << theta_deg << ',' << beta << ',' << result.impulse_Ns << ',' << result.prediction.impulse.exact_Ns << ','
             << relative(result.impulse_Ns, result.prediction.impulse.exact_Ns) << '\n';
    }
  }
}

// Scenario 1 does not depend on theta (the wheel meets the outgoing plane),
// so one scenario-1 series stands for all three junction angles.
void write_figure_4_7_data(const Scene& base, const fs::path& dir) {
  std::ofstream curves = open_csv(dir, "fig4_7_analytic.csv");
  std::ofstream points = open_csv(dir, "fig4_7_sim.csv");
  curves << "series,theta_deg,y_w_m,speed_m_per_s,exact_simulated_wheel_Ns,exact_thin_disc_Ns,thesis_thin_disc_Ns\n";
  points << "series,theta_deg,y_w_m,speed_m_per_s,sim_Ns,exact_Ns,error_exact\n";
  struct Series {
    const char* name;
    double theta_deg;
    double y_w_m;
  };
  for (const Series& series : {Series{"scenario 1", 30.0, 0.002}, Series{"scenario 2", 30.0, 0.015},
                               Series{"scenario 2", 45.0, 0.015}, Series{"scenario 2", 60.0, 0.015}}) {
    JointParams joint = base.joint;
    joint.theta_rad = radians(series.theta_deg);
    joint.beta_rad = 0.03;
    WheelParams disc = base.wheel;
    disc.lateral_m = series.y_w_m;
    disc.width_m = 0.0;
    for (int i = 0; i <= 50; ++i) {
      disc.speed_m_per_s = 1.0 + 59.0 * i / 50.0;
      const ImpactPrediction thin = predict_impact(joint, disc);
      curves << series.name << ',' << series.theta_deg << ',' << series.y_w_m << ',' << disc.speed_m_per_s << ','
             << predict_impact(joint, wheel_as_simulated(disc, base.sim)).impulse.exact_Ns << ','
             << thin.impulse.exact_Ns << ',' << thin.impulse.thesis_Ns << '\n';
    }
    for (double speed : {10.0, 20.0, 30.0, 40.0, 50.0}) {
      disc.speed_m_per_s = speed;
      const SimulationResult result = simulate_crossing(joint, disc, base.sim);
      points << series.name << ',' << series.theta_deg << ',' << series.y_w_m << ',' << speed << ','
             << result.impulse_Ns << ',' << result.prediction.impulse.exact_Ns << ','
             << relative(result.impulse_Ns, result.prediction.impulse.exact_Ns) << '\n';
    }
  }
}

// Points in millimetres would read better, but every CSV here is in SI units.
void write_figure_4_8_data(const Scene& base, const fs::path& dir) {
  std::ofstream loci = open_csv(dir, "fig4_8_analytic.csv");
  std::ofstream points = open_csv(dir, "fig4_8_sim.csv");
  loci << "theta_deg,y_t_m,half_width_m,y_w_m,slice_y_m,scenario,wheel_x_m,A_x_m,A_y_m,B_x_m,B_y_m\n";
  points << "theta_deg,y_w_m,impact_found,wheel_x_m,struck_x_m,struck_y_m,left_x_m,left_y_m,A_x_m,A_y_m,B_x_m,B_y_m\n";
  for (double theta_deg : {30.0, 45.0, 60.0, 90.0}) {
    JointParams joint = base.joint;
    joint.theta_rad = radians(theta_deg);
    joint.beta_rad = 0.03;
    WheelParams disc = base.wheel;
    disc.width_m = 0.0;
    const double b_t = joint.half_width_m;
    // The analytic loci of the thin disc (its simulated stand-in strikes as it does).
    for (int i = 0; i <= 80; ++i) {
      disc.lateral_m = b_t * i / 80.0;
      const ImpactPrediction p = predict_impact(joint, disc);
      loci << theta_deg << ',' << p.transition_y_m << ',' << b_t << ',' << disc.lateral_m << ',' << p.governing_y_m << ','
           << to_string(p.scenario) << ',' << p.impact_wheel_x_m << ',' << p.contact_A_m.x() << ','
           << p.contact_A_m.y() << ',' << p.contact_B_m.x() << ',' << p.contact_B_m.y() << '\n';
    }
    for (double y_w : {0.002, 0.006, 0.010, 0.014, 0.018}) {
      disc.lateral_m = y_w;
      const SimulationResult r = simulate_crossing(joint, disc, base.sim);
      const ImpactPrediction& p = r.prediction;
      points << theta_deg << ',' << y_w << ',' << (r.impact_found ? 1 : 0) << ',' << r.impact_x_m << ','
             << r.contact_struck_m.x() << ',' << r.contact_struck_m.y() << ',' << r.contact_left_m.x() << ','
             << r.contact_left_m.y() << ',' << p.contact_A_m.x() << ',' << p.contact_A_m.y() << ','
             << p.contact_B_m.x() << ',' << p.contact_B_m.y() << '\n';
    }
  }
}

}  // namespace railjoint::cli
