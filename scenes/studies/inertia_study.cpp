#include "scenes/studies/inertia_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>
#include <variant>

#include "models/kinematic_trajectory.h"
#include "models/liftoff.h"
#include "scenes/report/report_text.h"
#include "scenes/studies/study_table.h"
#include "sim/crossing_cases.h"
#include "sim/impact_force_estimate.h"
#include "sim/setting_checks.h"
#include "sim/simulate_crossing.h"

namespace railjoint {

namespace {

// The thesis's 1 m dip leaves no room for the flights: after a scenario-2
// strike at 50 m/s the wheel flies ~16 ms, 0.8 m. A 3 m linear dip keeps
// the same V (beta) and gives the outgoing rail 1.5 m.
constexpr double kJointLength_m = 3.0;
SimSettings inertial_settings(double speed_m_per_s) {
  SimSettings s;
  s.make_inertial();
  // End before the wheel leaves the outgoing rail (check_sim_settings: run_out v < 0.4 L).
  s.run_out_time_s = 0.38 * kJointLength_m / speed_m_per_s;
  return s;
}

CrossingCase study_crossing(double theta_deg, double lateral_m, double speed_m_per_s) {
  CrossingCase c = inclined_crossing("inertia", theta_deg, lateral_m, speed_m_per_s);
  c.joint.length_m = kJointLength_m;
  return c;
}

// The pivot angle at the joint for the wheel as simulated (the thin disc's
// stand-in): alpha, the radius to the corner A from the vertical.
double joint_pivot_angle_rad(const CrossingCase& c) {
  return predict_impact(c.joint, wheel_as_simulated(c.wheel, SimSettings{})).alpha_rad;
}

// The pivot model's flight (see InertiaSweepPoint::predicted_clearance_m):
// the ballistic centre path from where the pivot is lost, marched in x
// against the kinematic centre path until it comes back down onto it.
double predicted_clearance_m(const CrossingCase& c, const WheelParams& simulated, const ImpactPrediction& p,
                             const InertialOutcome& o) {
  const double M = c.wheel.mass_kg, R = c.wheel.radius_m, v = c.wheel.speed_m_per_s;
  const double W = o.static_load_N;
  const double g = W / M;
  double x0 = 0.0, z0 = 0.0, w0 = 0.0;
  if (!p.on_landing) {
    if (v <= pivot_liftoff_speed_m_per_s(M, R, W, o.pivot_angle_rad)) return 0.0;
    x0 = p.impact_wheel_x_m;
    z0 = p.impact_wheel_z_m;
    w0 = p.zdot_after_m_per_s;
  } else {
    // Pivot about the corner A from phi = beta/2 (leaving the incoming
    // slope) to alpha (landing); lost where cos^3(phi) = M v^2 / (W R).
    // The arc holds while cos^3(phi) >= demand = M v^2 / (W R).
    const double half = c.joint.beta_rad / 2.0;
    const double demand = M * v * v / (W * R);
    double phi = half;  // lost at once
    if (std::pow(std::cos(half), 3) >= demand) {
      phi = std::acos(std::cbrt(demand));
      if (phi >= o.pivot_angle_rad) return 0.0;
    }
    x0 = p.contact_A_m.x() + R * std::sin(phi);
    z0 = p.contact_A_m.z() + R * std::cos(phi);
    w0 = -v * std::tan(phi);
  }
  double clearance = 0.0;
  bool above = false;
  const KinematicPath path(c.joint, simulated);
  for (double dx = 1e-4; dx < 1.2; dx += 1e-4) {
    const double t = dx / v;
    const double z = z0 + w0 * t - 0.5 * g * t * t;
    const double d = z - path.centre_height_m(x0 + dx);
    if (d > 0.0) above = true;
    if (above && d <= 0.0) break;
    clearance = std::max(clearance, d);
  }
  return clearance;
}

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(n == 1 ? a : a + (b - a) * i / (n - 1));
  return out;
}

// One crossing of the sweep or of the compliant runs.
struct Crossing {
  double theta_deg, speed_m_per_s, lateral_m;
};

InertiaSweepPoint sweep_point(const Crossing& crossing) {
  const auto [theta_deg, speed, lateral] = crossing;
  const CrossingCase c = study_crossing(theta_deg, lateral, speed);
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, inertial_settings(speed));
  const InertialOutcome& o = *r.inertial();
  InertiaSweepPoint p;
  p.theta_deg = theta_deg;
  p.speed_m_per_s = speed;
  p.lateral_m = lateral;
  p.scenario = r.prediction().scenario;
  p.on_landing = r.prediction().on_landing;
  p.kinematic_jump_Ns = r.prediction().impulse.exact_Ns;
  p.first_jump_Ns = r.impact_found() ? r.impulse_Ns() : kNaN;
  if (o.joint_impact_index >= 0) {
    const std::size_t next = static_cast<std::size_t>(o.joint_impact_index) + 1;
    if (next < r.trajectory.impacts.size() && r.trajectory.impacts[next].landing) {
      p.landing_jump_Ns = r.trajectory.impacts[next].momentum_jump_Ns;
    }
  }
  p.total_impulse_Ns = o.total_impulse_Ns;
  p.impacts = static_cast<int>(r.trajectory.impacts.size());
  p.liftoff = !o.flights.empty();
  p.liftoff_predicted = o.liftoff_predicted;
  p.pivot_liftoff_speed_m_per_s = o.pivot_liftoff_speed_m_per_s;
  p.predicted_clearance_m = r.prediction().scenario == ImpactScenario::one
                                ? kNaN
                                : predicted_clearance_m(c, r.model->simulated_wheel, r.prediction(), o);
  for (const Flight& f : o.flights) {
    if (f.duration_s > p.flight_time_s) {
      p.flight_time_s = f.duration_s;
      p.apex_height_m = f.apex_height_m;
    }
  }
  p.max_deviation_m = o.max_deviation_m;
  p.ended_in_flight = o.ended_in_flight;
  p.wall_s = r.wall_seconds;
  return p;
}

struct ThresholdCase {
  std::string name;
  double theta_deg;
  double lateral_m;
  double flat_approach_m;
  double critical_speed_m_per_s;  ///< the load is chosen for it; 0: the service load
};

bool lifts_off(const ThresholdCase& t, double load_N, double speed) {
  CrossingCase c = study_crossing(t.theta_deg, t.lateral_m, speed);
  SimSettings s = inertial_settings(speed);
  s.run_out_time_s = std::min(*s.run_out_time_s, 0.005);
  s.inertial()->wheel_load_N = load_N;
  s.inertial()->flat_approach_m = t.flat_approach_m;
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, s);
  return !r.inertial()->flights.empty();
}

LiftoffThresholdPoint threshold_point(const ThresholdCase& t, int iterations) {
  const CrossingCase c = study_crossing(t.theta_deg, t.lateral_m, 30.0);
  const double M = c.wheel.mass_kg, R = c.wheel.radius_m;
  LiftoffThresholdPoint p;
  p.name = t.name;
  p.theta_deg = t.theta_deg;
  p.lateral_m = t.lateral_m;
  p.flat_approach_m = t.flat_approach_m;
  // The entry kink's arc ends at beta/2 from the vertical; the joint's pivot at phi.
  p.pivot_angle_rad = t.flat_approach_m > 0.0 ? c.joint.beta_rad / 2.0 : joint_pivot_angle_rad(c);
  double load = InertialSettings{}.wheel_load_N;
  if (t.critical_speed_m_per_s > 0.0) {
    load = pivot_following_load_N(M, R, t.critical_speed_m_per_s, p.pivot_angle_rad) - M * kStandardGravity_m_per_s2;
  }
  p.static_load_N = load + M * kStandardGravity_m_per_s2;
  p.model_speed_m_per_s = pivot_liftoff_speed_m_per_s(M, R, p.static_load_N, p.pivot_angle_rad);
  // Bisection on v within +-15 % of the model's speed.
  double lo = 0.85 * p.model_speed_m_per_s, hi = 1.15 * p.model_speed_m_per_s;
  const bool lo_lifts = lifts_off(t, load, lo), hi_lifts = lifts_off(t, load, hi);
  p.runs = 2;
  if (lo_lifts || !hi_lifts) {
    // Not bracketed: report the ends as found.
    p.sim_below_m_per_s = lo_lifts ? kNaN : hi;
    p.sim_above_m_per_s = hi_lifts ? lo : kNaN;
    return p;
  }
  for (int i = 0; i < iterations; ++i) {
    const double mid = 0.5 * (lo + hi);
    (lifts_off(t, load, mid) ? hi : lo) = mid;
    ++p.runs;
  }
  p.sim_below_m_per_s = lo;
  p.sim_above_m_per_s = hi;
  return p;
}

PeakForcePoint peak_point(const Crossing& crossing) {
  const auto [theta_deg, speed, lateral] = crossing;
  const CrossingCase c = study_crossing(theta_deg, lateral, speed);
  SimSettings s = inertial_settings(speed);
  s.run_out_time_s = 0.004;
  const double W = s.inertial()->wheel_load_N + c.wheel.mass_kg * kStandardGravity_m_per_s2;
  const double k = linearised_hertz_stiffness_N_per_m(HertzContact{}, W);
  // Undamped, as Jenkins's P1 assumes (a scene's default is critical).
  s.inertial()->contact = LinearContactSettings{k, 0.0};
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, s);
  PeakForcePoint p;
  p.theta_deg = theta_deg;
  p.lateral_m = lateral;
  p.speed_m_per_s = speed;
  p.static_load_N = W;
  p.stiffness_N_per_m = k;
  p.kinematic_jump_Ns = r.prediction().impulse.exact_Ns;
  p.jump_velocity_change_m_per_s = p.kinematic_jump_Ns / c.wheel.mass_kg;
  p.peak_force_N = r.inertial()->peak_force_N;
  p.p1_rigid_track_N = r.inertial()->compliant->rigid_track_p1_beta_v_N;
  p.p1_from_jump_N = r.inertial()->compliant->rigid_track_p1_N;
  const ImpactPrediction& model = r.prediction();
  p.scenario = model.scenario == ImpactScenario::two ? 2 : 1;
  if (p.scenario == 2) {
    const double lead_m = model.contact_A_m.x() - model.impact_wheel_x_m;
    p.edge_pivot_time_s = (lead_m + c.wheel.radius_m * std::sin(c.joint.beta_rad / 2.0)) / speed;
  }
  p.spring_quarter_period_s = 0.5 * std::numbers::pi * std::sqrt(c.wheel.mass_kg / k);
  return p;
}

}  // namespace

InertiaStudy run_inertia_study(bool quick, const ParallelRuns& parallel) {
  const auto start = std::chrono::steady_clock::now();
  InertiaStudy study;
  study.quick = quick;
  study.wheel_load_N = InertialSettings{}.wheel_load_N;
  study.joint_length_m = kJointLength_m;

  const std::vector<double> thetas = quick ? std::vector<double>{30.0} : std::vector<double>{30.0, 45.0, 60.0, 90.0};
  const std::vector<double> speeds = quick ? std::vector<double>{10.0, 30.0, 50.0} : linspace(10.0, 50.0, 9);
  // y_w over the rail head, 1.5 mm apart. The 1 mm disc keeps 1.5 mm from
  // the head's edges: flush with a side face (y_w = +-19.5 mm) it caught the
  // side edge (spurious jumps of ~100 N s, 0.1 mm sinking).
  const std::vector<double> laterals =
      quick ? std::vector<double>{-0.015, 0.0015, 0.015} : linspace(-0.018, 0.018, 25);
  std::vector<ThresholdCase> threshold_cases;
  if (quick) {
    threshold_cases = {{"scenario2_pivot_vc30", 30.0, 0.015, 0.0, 30.0}};
  } else {
    for (const double vc : {15.0, 30.0, 45.0}) {
      threshold_cases.push_back({"scenario2_pivot_vc" + format_number("%.0f", vc), 30.0, 0.015, 0.0, vc});
      threshold_cases.push_back({"step_down_pivot_vc" + format_number("%.0f", vc), 30.0, -0.015, 0.0, vc});
    }
    // Under the service load itself: v_c ~ 8.7 m/s at the joint's pivot as at the entry kink.
    threshold_cases.push_back({"scenario2_pivot_service_load", 30.0, 0.015, 0.0, 0.0});
    threshold_cases.push_back({"step_down_pivot_service_load", 30.0, -0.015, 0.0, 0.0});
    threshold_cases.push_back({"entry_kink_service_load", 30.0, 0.002, 0.5, 0.0});
  }
  const int iterations = quick ? 4 : 7;
  const std::vector<double> peak_speeds = quick ? std::vector<double>{50.0} : linspace(10.0, 50.0, 5);

  std::vector<Crossing> sweep_cases;
  for (const double theta : thetas) {
    for (const double v : speeds) {
      for (const double y : laterals) sweep_cases.push_back({theta, v, y});
    }
  }
  // Scenario 1 (theta 45 deg, y_w 2 mm) and the scenario-2 point of figure 4.5.
  std::vector<Crossing> peak_cases;
  for (const auto& [theta, y] : {std::pair{45.0, 0.002}, std::pair{30.0, 0.015}}) {
    for (const double v : peak_speeds) peak_cases.push_back({theta, v, y});
  }
  // One task list for every thread: the bisections first (each a chain of
  // runs: started last they would run on alone), then the compliant runs and the sweep.
  using Task = std::variant<LiftoffThresholdPoint, PeakForcePoint, InertiaSweepPoint>;
  const std::size_t thresholds = threshold_cases.size();
  const std::size_t peaks = peak_cases.size();
  const std::vector<Task> tasks =
      parallel_map<Task>(thresholds + peaks + sweep_cases.size(), parallel, [&](std::size_t k) -> Task {
        if (k < thresholds) return threshold_point(threshold_cases[k], iterations);
        if (k < thresholds + peaks) return peak_point(peak_cases[k - thresholds]);
        return sweep_point(sweep_cases[k - thresholds - peaks]);
      });
  for (const Task& task : tasks) {
    if (const auto* t = std::get_if<LiftoffThresholdPoint>(&task)) study.thresholds.push_back(*t);
    if (const auto* p = std::get_if<PeakForcePoint>(&task)) study.peaks.push_back(*p);
    if (const auto* p = std::get_if<InertiaSweepPoint>(&task)) study.sweep.push_back(*p);
  }
  study.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return study;
}

namespace {

// The sweep's CSV and its printed selection (theta 30 deg, three speeds, the
// lateral positions of the figures), each column once.
StudyTable sweep_table(const InertiaStudy& study) {
  StudyTable table({{"theta_deg"}, {"speed_m_per_s", "v [m/s]", "%.0f"}, {"y_w_m", "y_w [mm]", "%+.1f", 1e3},
                    {"scenario", "scenario"}, {"on_landing"}, {"kinematic_jump_Ns", "kinematic [N s]", "%.1f"},
                    {"first_jump_Ns", "first jump [N s]", "%.1f"}, {"landing_jump_Ns", "landing jump [N s]", "%.1f"},
                    {"total_impulse_Ns", "total [N s]", "%.1f"}, {"impacts"}, {"liftoff"}, {"liftoff_predicted"},
                    {"pivot_liftoff_speed_m_per_s"}, {"predicted_clearance_m"},
                    {"flight_time_s", "flight [ms]", "%.2f", 1e3}, {"apex_height_m", "apex [mm]", "%.3f", 1e3},
                    {"max_deviation_m"}, {"ended_in_flight"}, {"wall_s"}});
  for (const InertiaSweepPoint& p : study.sweep) {
    const bool selected_speed = p.speed_m_per_s == 10.0 || p.speed_m_per_s == 30.0 || p.speed_m_per_s == 50.0;
    const bool selected_y = std::abs(std::abs(p.lateral_m) - 0.015) < 1e-9 || std::abs(p.lateral_m - 0.0015) < 1e-9 ||
                            std::abs(p.lateral_m - 0.002) < 1e-9;
    const std::string scenario = to_string(p.scenario);
    table.add({p.theta_deg, p.speed_m_per_s, p.lateral_m, {scenario, scenario + (p.on_landing ? " landing" : "")},
               p.on_landing, p.kinematic_jump_Ns, p.first_jump_Ns, p.landing_jump_Ns, p.total_impulse_Ns, p.impacts,
               p.liftoff, p.liftoff_predicted, p.pivot_liftoff_speed_m_per_s, p.predicted_clearance_m, p.flight_time_s,
               p.apex_height_m, p.max_deviation_m, p.ended_in_flight, p.wall_s},
              p.theta_deg == 30.0 && selected_speed && selected_y ? StudyRowIn::both : StudyRowIn::csv);
  }
  return table;
}

StudyTable thresholds_table(const InertiaStudy& study) {
  StudyTable table({{"case", "pivot"}, {"theta_deg"}, {"y_w_m"}, {"flat_approach_m"},
                    {"pivot_angle_rad", "angle [rad]", "%.5f"}, {"static_load_N", "W [kN]", "%.1f", 1e-3},
                    {"model_speed_m_per_s", "model v_c [m/s]", "%.3f"}, {"", "simulated between [m/s]", "%s"},
                    {"sim_below_m_per_s"}, {"sim_above_m_per_s"}, {"", "sim / model - 1", "%+.2f %%", 100.0},
                    {"runs"}});
  for (const LiftoffThresholdPoint& p : study.thresholds) {
    const double mid = 0.5 * (p.sim_below_m_per_s + p.sim_above_m_per_s);
    table.add({p.name, p.theta_deg, p.lateral_m, p.flat_approach_m, p.pivot_angle_rad, p.static_load_N,
               p.model_speed_m_per_s,
               format_number("%.3f", p.sim_below_m_per_s) + " .. " + format_number("%.3f", p.sim_above_m_per_s),
               p.sim_below_m_per_s, p.sim_above_m_per_s, mid / p.model_speed_m_per_s - 1.0, p.runs});
  }
  return table;
}

// Peak force of the compliant contact against P1 with either velocity change.
StudyTable peaks_table(const InertiaStudy& study) {
  StudyTable table({{"theta_deg", "theta [deg]", "%.0f"}, {"y_w_m", "y_w [mm]", "%.1f", 1e3}, {"speed_m_per_s"},
                    {"scenario", "scenario", "%d"}, {"", "v [m/s]", "%.0f"},
                    {"static_load_N", "P0 [kN]", "%.1f", 1e-3}, {"stiffness_N_per_m"}, {"kinematic_jump_Ns"},
                    {"peak_force_N", "peak [kN]", "%.1f", 1e-3},
                    {"p1_rigid_track_N", "P1(beta v) [kN]", "%.1f", 1e-3},
                    {"", "peak / P1(beta v) - 1", "%+.2f %%", 100.0}, {"", "Delta p / M [m/s]", "%.3f"},
                    {"p1_from_jump_N", "P1(Delta p / M) [kN]", "%.1f", 1e-3},
                    {"", "peak / P1(Delta p / M) - 1", "%+.2f %%", 100.0}, {"edge_pivot_time_s"},
                    {"spring_quarter_period_s"}, {"", "pivot / rise time", "%s"}});
  for (const PeakForcePoint& p : study.peaks) {
    table.add({p.theta_deg, p.lateral_m, p.speed_m_per_s, p.scenario, p.speed_m_per_s, p.static_load_N,
               p.stiffness_N_per_m, p.kinematic_jump_Ns, p.peak_force_N, p.p1_rigid_track_N,
               p.peak_force_N / p.p1_rigid_track_N - 1.0, p.jump_velocity_change_m_per_s, p.p1_from_jump_N,
               p.peak_force_N / p.p1_from_jump_N - 1.0, p.edge_pivot_time_s, p.spring_quarter_period_s,
               p.scenario == 2 ? StudyCell(format_number("%.2f", p.edge_pivot_time_s / p.spring_quarter_period_s))
                               : StudyCell()});
  }
  return table;
}

}  // namespace

void write_inertia_csvs(const InertiaStudy& study, const CsvFiles& files) {
  const std::pair<const char*, StudyTable> tables[] = {{"inertia_sweep.csv", sweep_table(study)},
                                                       {"inertia_thresholds.csv", thresholds_table(study)},
                                                       {"inertia_peaks.csv", peaks_table(study)}};
  for (const auto& [name, table] : tables) {
    AtomicFile out = files(name);
    table.write_csv(out);
    out.commit();
  }
}

std::string inertia_report(const InertiaStudy& study) {
  std::ostringstream out;
  char line[512];
  std::snprintf(line, sizeof line,
                "# Inertia: the wheel not glued to the rail\n\n"
                "Inertial mode: weight + %.4g N wheel load (thesis table 6.1), horizontal speed held, rigid plastic "
                "frictionless contact, %g m linear dip (thesis beta = 0.03 rad), 1 mm disc. %zu crossings, %.1f s.\n\n",
                study.wheel_load_N, study.joint_length_m, study.sweep.size(), study.wall_s);
  out << line;

  StudyTable angles({{"", "theta [deg]", "%.0f"}, {"", "scenario 1 points", "%d"},
                     {"", "max abs(first / kinematic - 1)", "%.3f %%", 100.0}, {"", "with lift-off", "%d"},
                     {"", "scenario 2 / step points", "%d"}, {"", "with lift-off", "%d"}, {"", "predicted", "%d"},
                     {"", "total / kinematic (mean, max)", "%s"}});
  std::vector<double> thetas;
  for (const InertiaSweepPoint& p : study.sweep) {
    if (std::find(thetas.begin(), thetas.end(), p.theta_deg) == thetas.end()) thetas.push_back(p.theta_deg);
  }
  for (const double theta : thetas) {
    int n1 = 0, lift1 = 0, n2 = 0, lift2 = 0, predicted2 = 0;
    double worst1 = 0.0, sum_ratio = 0.0, max_ratio = 0.0;
    for (const InertiaSweepPoint& p : study.sweep) {
      if (p.theta_deg != theta) continue;
      const double ratio = p.total_impulse_Ns / p.kinematic_jump_Ns;
      if (p.scenario == ImpactScenario::one) {
        ++n1;
        lift1 += p.liftoff;
        worst1 = std::max(worst1, std::abs(p.first_jump_Ns / p.kinematic_jump_Ns - 1.0));
      } else {
        ++n2;
        lift2 += p.liftoff;
        predicted2 += p.liftoff_predicted;
        sum_ratio += ratio;
        max_ratio = std::max(max_ratio, ratio);
      }
    }
    angles.add({theta, n1, worst1, lift1, n2, lift2, predicted2,
                format_number("%.3f", n2 > 0 ? sum_ratio / n2 : 0.0) + ", " + format_number("%.3f", max_ratio)});
  }
  out << "## Sweep, per junction angle\n\n" << angles.markdown();

  out << "\n## Selected crossings (theta 30 deg)\n\n" << sweep_table(study).markdown();
  out << "\n## Lift-off speed: pivot model against the simulation (bisection)\n\n"
      << thresholds_table(study).markdown();
  out << "\n## Compliant contact: peak force against P1 (Jenkins et al. 1974, rigid track)\n\n"
         "P1 = P0 + dv sqrt(k M) with dv = beta v (Jenkins's 2 alpha v: the path turns by the dip angle) and with\n"
         "dv = Delta p / M (the kinematic jump). They agree in scenario 1; in scenario 2 the rigid wheel strikes\n"
         "the cut edge harder and then pivots over it. When that pivot is shorter than the spring's rise time\n"
         "(pi/2) sqrt(M/k), the spring feels the net change beta v.\n\n";
  if (!study.peaks.empty()) {
    out << "k = " << format_number("%.4g", study.peaks.front().stiffness_N_per_m)
        << " N/m: the Hertz contact of the wheel on the rail crown linearised at P0 (sim/impact_force_estimate.h).\n\n";
  }
  out << peaks_table(study).markdown();
  return out.str();
}

}  // namespace railjoint
