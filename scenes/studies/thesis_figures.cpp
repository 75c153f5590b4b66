// The data behind the thesis's figures redrawn by `railjoint validate`
// (thesis_figures.h). Simulated points always use the wheel as simulated (a
// thin disc is a 1 mm wide cylinder) and are compared with that wheel's
// analytic values; thin-disc curves are written beside them.

#include "scenes/studies/thesis_figures.h"

#include <algorithm>
#include <numbers>
#include <utility>
#include <vector>

#include "models/impact_prediction.h"
#include "models/jump_error.h"
#include "models/time_history.h"
#include "scenes/report/prediction_csv.h"
#include "scenes/scene_file.h"
#include "scenes/studies/study_table.h"
#include "sim/setting_checks.h"
#include "sim/simulate_crossing.h"
#include "sim/time_origin.h"
#include "support/case_pool.h"

namespace railjoint {

namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// The thesis's defaults with the cut at theta and a thin disc at y_w.
std::pair<JointParams, WheelParams> thin_disc_case(const Scene& base, double theta_deg, double y_w_m) {
  JointParams joint = base.joint;
  joint.theta_rad = radians(theta_deg);
  WheelParams disc = base.wheel;
  disc.lateral_m = y_w_m;
  disc.width_m = 0.0;
  return {joint, disc};
}

// The crossings of a figure, each on one of `jobs` threads (a Bullet world
// each), results in their order.
std::vector<SimulationResult> simulate_all(const std::vector<std::pair<JointParams, WheelParams>>& crossings,
                                           const SimSettings& sim, int jobs) {
  return parallel_map<SimulationResult>(crossings.size(), {jobs, ""}, [&](std::size_t i) {
    return simulate_crossing(crossings[i].first, crossings[i].second, sim);
  });
}

// n + 1 values from `first` to first + span, evenly spaced.
std::vector<double> curve_grid(double first, double span, int n) {
  std::vector<double> values;
  for (int i = 0; i <= n; ++i) values.push_back(first + span * i / n);
  return values;
}

// A figure's analytic curves (FIGURE_analytic.csv) and simulated points
// (FIGURE_sim.csv), each a table of the header's columns; the files are
// opened first and committed once both are written.
struct CurvesAndPoints {
  AtomicFile curves_file, points_file;
  StudyTable curves, points;
  CurvesAndPoints(const CsvFiles& files, const std::string& figure, const char* curve_columns,
                  const char* point_columns)
      : curves_file(files(figure + "_analytic.csv")), points_file(files(figure + "_sim.csv")),
        curves(StudyTable::csv_only(curve_columns)), points(StudyTable::csv_only(point_columns)) {}
  void commit() {
    curves.write_csv(curves_file);
    points.write_csv(points_file);
    curves_file.commit();
    points_file.commit();
  }
};

std::vector<StudyCell> row_of(std::vector<StudyCell> row, std::initializer_list<StudyCell> more) {
  row.insert(row.end(), more);
  return row;
}

// One series of figs. 4.6 / 4.7: the analytic curves at `curve_values` and
// the simulated points at `point_values` of the swept parameter (`set` puts a
// value into the joint or the wheel). Each row starts with the series'
// columns (`prefix`) and the value. A curve row: the exact jump of the wheel
// as simulated (a narrow cylinder whose inner face governs), the thin disc's
// exact and printed forms, and its scenario when `with_scenario`. A point:
// the simulated jump, the exact one it is compared with and the error; NaN
// for the jump and the error when no impact was found (a 0 would plot as -100 %).
template <class Set>
void write_series(CurvesAndPoints& out, const std::vector<StudyCell>& prefix, JointParams joint, WheelParams disc,
                  const SimSettings& sim, const std::vector<double>& curve_values,
                  const std::vector<double>& point_values, Set set, bool with_scenario, int jobs) {
  for (const double value : curve_values) {
    set(joint, disc, value);
    const ImpactPrediction thin = predict_impact(joint, disc);
    const double simulated_wheel_Ns = predict_impact(joint, wheel_as_simulated(disc, sim)).impulse.exact_Ns;
    std::vector<StudyCell> row = row_of(prefix, {value, simulated_wheel_Ns, thin.impulse.exact_Ns, thin.impulse.thesis_Ns});
    if (with_scenario) row.push_back(to_string(thin.scenario));
    out.curves.add(std::move(row));
  }
  std::vector<std::pair<JointParams, WheelParams>> crossings;
  for (const double value : point_values) {
    set(joint, disc, value);
    crossings.emplace_back(joint, disc);
  }
  const std::vector<SimulationResult> results = simulate_all(crossings, sim, jobs);
  for (std::size_t i = 0; i < point_values.size(); ++i) {
    const SimulationResult& r = results[i];
    const double exact = r.prediction().impulse.exact_Ns;
    const double jump = r.impact_found() ? r.impulse_Ns() : kNaN;
    const double error = r.impact_found() ? relative_error(jump, exact) : kNaN;
    out.points.add(row_of(prefix, {point_values[i], jump, exact, error}));
  }
}

// A simulated history of figs. 3.7 / 4.5 on the outputs' convention
// (outputs.md): t = 0 when the centre passes the predicted impact position
// of `p` (the analytic curve beside it), x and z in the joint frame.
void write_simulated_history(std::ostream& out, const SimulationResult& result, const ImpactPrediction& p) {
  const std::vector<WheelSample>& samples = result.trajectory.samples;
  const double t0_s = passage_time_s(samples, p.impact_wheel_x_m);
  const double mass_kg = result.model->simulated_wheel.mass_kg;
  StudyTable table = StudyTable::csv_only("t_s,x_m,z_m,zdot_m_per_s,momentum_Ns");
  for (const WheelSample& s : samples) {
    const double zdot = s.velocity_m_per_s.z();
    table.add({s.time_s - t0_s, s.centre_m.x(), s.centre_m.z(), zdot, mass_kg * zdot});
  }
  table.write_csv(out);
}

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

// Fig. 3.7: fig3_7_analytic.csv, fig3_7_sim.csv, fig3_7_jump.csv. One simulation.
void write_figure_3_7_data(const Scene& base, const CsvFiles& files) {
  const Scene scene = parse_scene(kFigure37Scene, "figure 3.7 scene");
  const SimulationResult result = simulate_crossing(scene.joint, scene.wheel, base.sim);
  const ImpactPrediction& p = result.prediction();
  const double v = scene.wheel.speed_m_per_s;

  AtomicFile sim = files("fig3_7_sim.csv");
  write_simulated_history(sim, result, p);
  // From 2 ms before the contact until the centre is over the edge (the end
  // of the kinematic pivot): 14.3 ms at 50 m/s.
  AtomicFile analytic = files("fig3_7_analytic.csv");
  write_time_history_csv(impact_time_history(scene.joint, scene.wheel, 2e-3, -p.impact_wheel_x_m / v, 2001), p, v,
                         analytic);
  // Each jump at its time on the histories' clock: the forms' at t = 0.
  AtomicFile jump = files("fig3_7_jump.csv");
  StudyTable jumps = StudyTable::csv_only("form,jump_Ns,time_s");
  jumps.add({"exact", p.impulse.exact_Ns, 0});
  jumps.add({"thesis", p.impulse.thesis_Ns, 0});
  jumps.add({"small_angle", p.impulse.small_angle_Ns, 0});
  jumps.add({"simulated", result.impulse_Ns(),
             result.impact ? passage_time_s(result.trajectory.samples, result.impact->wheel_x_m()) -
                                 passage_time_s(result.trajectory.samples, p.impact_wheel_x_m)
                           : kNaN});
  jumps.write_csv(jump);
  sim.commit();
  analytic.commit();
  jump.commit();
}

// Fig. 4.3: y_t against beta for theta = 30, 45, 60 deg (analytic only): fig4_3_analytic.csv.
void write_figure_4_3_data(const Scene& base, const CsvFiles& files) {
  AtomicFile out = files("fig4_3_analytic.csv");
  StudyTable table = StudyTable::csv_only("theta_deg,beta_rad,y_t_m");
  for (double theta_deg : {30.0, 45.0, 60.0}) {
    JointParams joint = base.joint;
    joint.theta_rad = radians(theta_deg);
    for (int i = 0; i <= 100; ++i) {
      joint.beta_rad = 0.05 * i / 100.0;
      table.add({theta_deg, joint.beta_rad, predict_impact(joint, base.wheel).transition_y_m});
    }
  }
  table.write_csv(out);
  out.commit();
}

// Fig. 4.5: a validation scene's simulated and analytic time histories
// (t = 0 at the predicted impact, x and z in the joint frame:
// scenes/report/outputs.md): <scene>_sim.csv, <scene>_analytic.csv.
void write_figure_4_5_data(const Scene& scene, const SimulationResult& result, const CsvFiles& files) {
  const ImpactPrediction& p = result.prediction();
  const double v = result.model->simulated_wheel.speed_m_per_s;
  AtomicFile sim = files(scene.name + "_sim.csv");
  write_simulated_history(sim, result, p);
  // From 10 mm before the V bottom to 12 mm after it (at least 2 mm past the impact).
  const double travel_before_m = 0.010 + std::max(0.0, p.impact_wheel_x_m);
  const double travel_after_m = 0.012 - std::max(0.0, p.impact_wheel_x_m);
  const TimeHistory h = impact_time_history(scene.joint, result.model->simulated_wheel, travel_before_m / v,
                                            std::max(travel_after_m, 0.002) / v, 2001);
  AtomicFile analytic = files(scene.name + "_analytic.csv");
  write_time_history_csv(h, p, v, analytic);
  sim.commit();
  analytic.commit();
}

// Fig. 4.6: impulse against beta at y_w = 15 mm, 15 simulations. The
// simulated "disc" has a small width whose inner face governs, so the
// simulated points are compared with the exact curve of that wheel; the
// thin-disc curves (exact and as printed) are drawn beside it.
void write_figure_4_6_data(const Scene& base, const CsvFiles& files, int jobs) {
  CurvesAndPoints out(files, "fig4_6",
                      "theta_deg,beta_rad,exact_simulated_wheel_Ns,exact_thin_disc_Ns,thesis_thin_disc_Ns,scenario",
                      "theta_deg,beta_rad,sim_Ns,exact_Ns,error_exact");
  for (double theta_deg : {30.0, 45.0, 60.0}) {
    const auto [joint, disc] = thin_disc_case(base, theta_deg, 0.015);
    write_series(
        out, {theta_deg}, joint, disc, base.sim,
        curve_grid(0.0005, 0.0495, 100), {0.01, 0.02, 0.03, 0.04, 0.05},
        [](JointParams& j, WheelParams&, double beta) { j.beta_rad = beta; }, true, jobs);
  }
  out.commit();
}

// Fig. 4.7: impulse against v, 20 simulations. Scenario 1 does not depend
// on theta (the wheel meets the outgoing plane), so one scenario-1 series
// stands for all three junction angles.
void write_figure_4_7_data(const Scene& base, const CsvFiles& files, int jobs) {
  CurvesAndPoints out(files, "fig4_7",
                      "series,theta_deg,y_w_m,speed_m_per_s,exact_simulated_wheel_Ns,exact_thin_disc_Ns,"
                      "thesis_thin_disc_Ns",
                      "series,theta_deg,y_w_m,speed_m_per_s,sim_Ns,exact_Ns,error_exact");
  struct Series {
    const char* name;
    double theta_deg;
    double y_w_m;
  };
  for (const Series& series : {Series{"scenario 1", 30.0, 0.002}, Series{"scenario 2", 30.0, 0.015},
                               Series{"scenario 2", 45.0, 0.015}, Series{"scenario 2", 60.0, 0.015}}) {
    auto [joint, disc] = thin_disc_case(base, series.theta_deg, series.y_w_m);
    joint.beta_rad = 0.03;
    write_series(
        out, {series.name, series.theta_deg, series.y_w_m}, joint, disc, base.sim, curve_grid(1.0, 59.0, 50), {10.0, 20.0, 30.0, 40.0, 50.0},
        [](JointParams&, WheelParams& w, double speed) { w.speed_m_per_s = speed; }, false, jobs);
  }
  out.commit();
}

// Fig. 4.8: contact points A and B and the wheel centre at two-point contact,
// top view, theta = 30, 45, 60, 90 deg, beta = 0.03, 20 simulations; in SI
// units as every CSV here.
void write_figure_4_8_data(const Scene& base, const CsvFiles& files, int jobs) {
  CurvesAndPoints out(
      files, "fig4_8", "theta_deg,y_t_m,half_width_m,y_w_m,slice_y_m,scenario,wheel_x_m,A_x_m,A_y_m,B_x_m,B_y_m",
      "theta_deg,y_w_m,impact_found,wheel_x_m,struck_x_m,struck_y_m,left_x_m,left_y_m,A_x_m,A_y_m,B_x_m,B_y_m");
  std::vector<std::pair<JointParams, WheelParams>> crossings;
  std::vector<std::pair<double, double>> labels;  // theta [deg], y_w [m], as the figure names them
  for (double theta_deg : {30.0, 45.0, 60.0, 90.0}) {
    auto [joint, disc] = thin_disc_case(base, theta_deg, base.wheel.lateral_m);
    joint.beta_rad = 0.03;
    const double b_t = joint.half_width_m;
    // The analytic loci of the thin disc (its simulated stand-in strikes as it does).
    for (int i = 0; i <= 80; ++i) {
      disc.lateral_m = b_t * i / 80.0;
      const ImpactPrediction p = predict_impact(joint, disc);
      out.curves.add({theta_deg, p.transition_y_m, b_t, disc.lateral_m, p.governing_y_m, to_string(p.scenario),
                      p.impact_wheel_x_m, p.contact_A_m.x(), p.contact_A_m.y(), p.contact_B_m.x(), p.contact_B_m.y()});
    }
    for (double y_w : {0.002, 0.006, 0.010, 0.014, 0.018}) {
      disc.lateral_m = y_w;
      crossings.emplace_back(joint, disc);
      labels.emplace_back(theta_deg, y_w);
    }
  }
  const std::vector<SimulationResult> results = simulate_all(crossings, base.sim, jobs);
  for (std::size_t i = 0; i < results.size(); ++i) {
    const SimulationResult& r = results[i];
    const ImpactPrediction& p = r.prediction();
    // Without an impact nothing was measured: NaN, which the figure script leaves out.
    const Eigen::Vector3d nan_point = Eigen::Vector3d::Constant(kNaN);
    const Eigen::Vector3d struck = r.impact ? r.impact->struck_point_m() : nan_point;
    const Eigen::Vector3d left = r.impact ? r.impact->left_point_m() : nan_point;
    out.points.add({labels[i].first, labels[i].second, r.impact_found(), r.impact ? r.impact->wheel_x_m() : kNaN,
                    struck.x(), struck.y(), left.x(), left.y(), p.contact_A_m.x(), p.contact_A_m.y(), p.contact_B_m.x(),
                    p.contact_B_m.y()});
  }
  out.commit();
}

}  // namespace

std::vector<std::string> write_thesis_figure_data(const std::vector<ValidationRow>& rows, const CsvFiles& files,
                                                  int jobs, const FigureProgress& progress) {
  std::vector<std::string> figure_4_5_scenes;
  for (const ValidationRow& r : rows) {
    if (r.scene.name == "s1_theta30" || r.scene.name == "s2_theta30" || r.scene.name == "s2_theta45" ||
        r.scene.name == "s2_theta60") {
      write_figure_4_5_data(r.scene, r.result, files);
      figure_4_5_scenes.push_back(r.scene.name);
    }
  }
  // The other figures vary one parameter of the thesis's defaults.
  const Scene base = parse_scene("", "thesis defaults");
  const auto figure = [&](std::size_t i, const char* label, auto writer) {
    if (progress) progress(i, 5, label);
    writer();
  };
  figure(0, "figure 3.7: the 0.3 m step, 1 simulation", [&] { write_figure_3_7_data(base, files); });
  figure(1, "figure 4.3: y_t (analytic)", [&] { write_figure_4_3_data(base, files); });
  figure(2, "figure 4.6: impulse against beta, 15 simulations", [&] { write_figure_4_6_data(base, files, jobs); });
  figure(3, "figure 4.7: impulse against v, 20 simulations", [&] { write_figure_4_7_data(base, files, jobs); });
  figure(4, "figure 4.8: contact points, 20 simulations", [&] { write_figure_4_8_data(base, files, jobs); });
  return figure_4_5_scenes;
}

}  // namespace railjoint
