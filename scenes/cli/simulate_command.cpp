// `railjoint simulate`: the Bullet crossing of one scene, its measured
// vertical momentum jump and the error against the three analytic forms; in
// inertial mode also every contact phase, flight and impact, the lift-off
// model and (compliant contact) the peak force against the P1 estimate.

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/kinematic_trajectory.h"
#include "models/parameter_error.h"
#include "scenes/cli/commands.h"
#include "renders/offscreen_renderer.h"
#include "scenes/cli/render_output.h"
#include "scenes/input_error.h"
#include "scenes/prediction_json.h"
#include "scenes/scene_file.h"
#include "scenes/studies/report_text.h"
#include "sim/contact_phases.h"
#include "sim/crossing_model.h"
#include "sim/simulate_crossing.h"

namespace railjoint::cli {

namespace {

struct SimulateOptions {
  std::string scene_path;
  std::vector<std::string> overrides;
  bool json = false;
  std::string csv_path;
  std::string render_dir = "out/render";
};

double relative_error(double simulated, double form) { return (simulated - form) / form; }

// Without an impact there is no measured jump: null, never a 0 that reads as -100 %.
nlohmann::json measured_or_null(bool impact_found, double value) {
  return impact_found ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json vector_json(const Eigen::Vector3d& v) {
  if (!v.allFinite()) return nullptr;
  return nlohmann::json::array({v.x(), v.y(), v.z()});
}

nlohmann::json number_or_null(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

nlohmann::json impacts_json(const SimulationResult& r) {
  nlohmann::json list = nlohmann::json::array();
  for (const ImpactEvent& e : r.trajectory.impacts) {
    nlohmann::json item = {{"time", e.time_s},
                           {"x", e.wheel_x_m},
                           {"jump", e.momentum_jump_Ns},
                           {"horizontal_impulse", e.horizontal_impulse_Ns},
                           {"contact_point", vector_json(e.contact_point_m)},
                           {"landing", e.landing}};
    if (r.inertial && r.inertial->compliant) item["peak_force"] = e.peak_force_N;
    list.push_back(item);
  }
  return list;
}

nlohmann::json inertial_json(const InertialOutcome& o, bool impact_found) {
  nlohmann::json j;
  j["wheel_load"] = o.wheel_load_N;
  j["static_load"] = o.static_load_N;
  j["horizontal"] = to_string(o.horizontal);
  j["carrier_mass"] = o.carrier_mass_kg;
  j["spinning"] = o.spinning;
  j["flat_approach"] = o.flat_approach_m;
  j["joint_impact_index"] = o.joint_impact_index;
  j["total_impulse"] = o.total_impulse_Ns;
  j["max_deviation"] = o.max_deviation_m;
  j["max_deviation_x"] = o.max_deviation_x_m;
  j["max_rise"] = o.max_rise_m;
  j["max_sink"] = o.max_sink_m;
  j["followed_kinematic_path"] = o.followed_kinematic_path;
  j["ended_in_flight"] = o.ended_in_flight;
  nlohmann::json phases = nlohmann::json::array();
  for (const ContactPhase& p : o.phases) {
    phases.push_back({{"contact", p.in_contact},
                      {"start_time", p.start_time_s},
                      {"end_time", p.end_time_s},
                      {"start_x", p.start_x_m},
                      {"end_x", p.end_x_m}});
  }
  j["phases"] = phases;
  nlohmann::json flights = nlohmann::json::array();
  for (const Flight& f : o.flights) {
    flights.push_back({{"liftoff_time", f.liftoff_time_s},
                       {"liftoff_x", f.liftoff_x_m},
                       {"liftoff_zdot", f.liftoff_zdot_m_per_s},
                       {"landed", f.landed},
                       {"landing_time", number_or_null(f.landing_time_s)},
                       {"landing_x", number_or_null(f.landing_x_m)},
                       {"duration", f.duration_s},
                       {"apex_height", f.apex_height_m},
                       {"max_clearance", f.max_clearance_m}});
  }
  j["flights"] = flights;
  j["liftoff_model"] = {{"pivot_angle", number_or_null(o.pivot_angle_rad)},
                        {"pivot_liftoff_speed", number_or_null(o.pivot_liftoff_speed_m_per_s)},
                        {"entry_kink_liftoff_speed", number_or_null(o.entry_kink_liftoff_speed_m_per_s)},
                        {"predicted", o.liftoff_predicted}};
  j["horizontal_motion"] = {{"xdot_before", o.xdot_before_m_per_s},
                            {"xdot_after", o.xdot_after_m_per_s},
                            {"joint_horizontal_impulse", o.joint_horizontal_impulse_Ns}};
  if (o.compliant) {
    j["compliant"] = {{"stiffness", o.contact_stiffness_N_per_m},
                      {"damping", o.contact_damping_N_s_per_m},
                      {"peak_force", measured_or_null(impact_found, o.peak_force_N)},
                      {"peak_force_time", measured_or_null(impact_found, o.peak_force_time_s)},
                      {"peak_force_x", measured_or_null(impact_found, o.peak_force_x_m)},
                      {"rigid_track_p1", o.rigid_track_p1_N},
                      {"rigid_track_p1_beta_v", o.rigid_track_p1_beta_v_N}};
  }
  return j;
}

nlohmann::json result_json(const SimulationResult& r) {
  nlohmann::json out;
  // `analytic` is exactly `railjoint analytic --json` of the scene. The run is
  // compared with `analytic_as_simulated`, the wheel Bullet holds: a thin disc
  // becomes a 2 sim.disc_half_width cylinder whose inner face governs.
  out["analytic"] = prediction_to_json(r.thin_disc_prediction ? *r.thin_disc_prediction : r.prediction);
  out["analytic_as_simulated"] = prediction_to_json(r.prediction);
  nlohmann::json sim;
  sim["impact_found"] = r.impact_found;
  if (!r.inertial) {
    // The run's own check (sim/self_check.h); inertial runs are judged by their phases instead.
    sim["verdict"] = r.verdict.ok ? "ok" : "suspect";
    sim["verdict_reason"] = r.verdict.reason;
  }
  sim["impulse"] = measured_or_null(r.impact_found, r.impulse_Ns);
  sim["impulse_from_contacts"] = measured_or_null(r.impact_found, r.impulse_from_contacts_Ns);
  sim["impact_time"] = measured_or_null(r.impact_found, r.impact_time_s);
  sim["impact_x"] = measured_or_null(r.impact_found, r.impact_x_m);
  sim["zdot_before"] = measured_or_null(r.impact_found, r.zdot_before_m_per_s);
  sim["zdot_after"] = measured_or_null(r.impact_found, r.zdot_after_m_per_s);
  sim["contact_struck"] = vector_json(r.contact_struck_m);
  sim["contact_left"] = vector_json(r.contact_left_m);
  sim["max_penetration"] = r.max_penetration_m;
  sim["liftoff"] = r.liftoff;
  sim["liftoff_time"] = r.liftoff ? nlohmann::json(r.liftoff_time_s) : nlohmann::json(nullptr);
  sim["second_impact"] = r.second_impact;
  sim["second_impact_time"] = r.second_impact ? nlohmann::json(r.second_impact_time_s) : nlohmann::json(nullptr);
  sim["second_impulse"] = r.second_impact ? nlohmann::json(r.second_impulse_Ns) : nlohmann::json(nullptr);
  sim["preload"] = r.preload_N;
  sim["simulated_width"] = r.simulated_wheel.width_m;
  sim["wall_seconds"] = r.wall_seconds;
  sim["steps"] = r.steps;
  sim["refined_steps"] = r.refined_steps;
  sim["impacts"] = impacts_json(r);
  if (r.inertial) {
    sim["mode"] = "inertial";
    sim["total_impulse"] = r.inertial->total_impulse_Ns;
    const nlohmann::json inertial = inertial_json(*r.inertial, r.impact_found);
    sim["flights"] = inertial["flights"];
    sim["phases"] = inertial["phases"];
    if (r.inertial->compliant) sim["peak_force"] = inertial["compliant"]["peak_force"];
    sim["inertial"] = inertial;
  } else {
    sim["mode"] = "kinematic";
  }
  out["sim"] = sim;
  const ImpulseForms& f = r.prediction.impulse;
  out["error"] = {{"exact", measured_or_null(r.impact_found, relative_error(r.impulse_Ns, f.exact_Ns))},
                  {"thesis", measured_or_null(r.impact_found, relative_error(r.impulse_Ns, f.thesis_Ns))},
                  {"small_angle", measured_or_null(r.impact_found, relative_error(r.impulse_Ns, f.small_angle_Ns))}};
  if (r.thin_disc_prediction) {
    out["error_vs_scene_wheel"] = {
        {"exact", measured_or_null(r.impact_found, relative_error(r.impulse_Ns, r.thin_disc_prediction->impulse.exact_Ns))}};
  }
  return out;
}

void write_csv(const Scene& scene, const SimulationResult& r, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw InputError(path, "--csv", "cannot write this file (does its folder exist?)");
  out.precision(12);
  out << "t_s,x_m,z_m,zdot_m_per_s,contacts,contact_impulse_z_Ns,xdot_m_per_s,contact_force_z_N,z_kinematic_m,"
         "spin_rate_rad_per_s\n";
  const double flat = r.inertial ? r.inertial->flat_approach_m : 0.0;
  const std::vector<WheelSample>& samples = r.trajectory.samples;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const WheelSample& s = samples[k];
    double impulse_z = 0;
    for (const ContactSample& c : s.contacts) impulse_z += c.normal_impulse_Ns * c.normal.z();
    const double z_kinematic = inertial_reference_height_m(scene.joint, r.simulated_wheel, flat, s.centre_m.x());
    out << s.time_s << ',' << s.centre_m.x() << ',' << s.centre_m.z() << ',' << s.velocity_m_per_s.z() << ','
        << s.contacts.size() << ',' << impulse_z << ',' << s.velocity_m_per_s.x() << ','
        << vertical_contact_force_N(samples, k) << ',' << z_kinematic << ',' << s.spin_rate_rad_per_s << '\n';
  }
}

void print_form(const char* name, double form, double simulated) {
  std::printf("  %-20s %s   sim error %s\n", name, format_finite("%12.4f N s", form, "         n/a    ").c_str(),
              format_finite("%+.4f %%", 100.0 * relative_error(simulated, form)).c_str());
}

void print_summary(const Scene& scene, const SimulationResult& r) {
  const ImpactPrediction& p = r.prediction;
  std::printf("scene  %s (%s)\n", scene.name.c_str(), scene.file.c_str());
  std::printf("sim    Bullet (double), mode %s, dt %.3g s refined to %.3g s, margin %.3g m, slop %.3g m, %s %.4g N\n",
              to_string(scene.sim.mode), scene.sim.time_step_s, scene.sim.refined_time_step_s, scene.sim.margin_m,
              scene.sim.slop_m, r.inertial ? "wheel load" : "preload", r.preload_N);
  if (r.thin_disc_prediction) {
    std::printf("       thin disc simulated as a cylinder of width %.3f mm: governing slice y = %.3f mm\n",
                r.simulated_wheel.width_m * 1e3, p.governing_y_m * 1e3);
  }
  std::printf("       %d steps (%d refined), %.2f ms wall\n", r.steps, r.refined_steps, r.wall_seconds * 1e3);
  if (!r.impact_found) {
    std::printf("no impact found\n");
    return;
  }
  std::printf("impact at t = %.6f ms, wheel x = %.4f mm (predicted %.4f mm)\n", r.impact_time_s * 1e3,
              r.impact_x_m * 1e3, p.impact_wheel_x_m * 1e3);
  // On landing (step down) the wheel strikes the far rail at the prediction's
  // B after pivoting about A, the corner it leaves; otherwise it strikes A.
  const Eigen::Vector3d& struck_predicted = p.on_landing ? p.contact_B_m : p.contact_A_m;
  const Eigen::Vector3d& left_predicted = p.on_landing ? p.contact_A_m : p.contact_B_m;
  const char* struck_name = p.on_landing ? "B" : "A";
  const char* left_name = p.on_landing ? "A" : "B";
  std::printf("       struck (%.3f, %.3f, %.4f) mm, predicted %s (%.3f, %.3f, %.4f) mm\n", r.contact_struck_m.x() * 1e3,
              r.contact_struck_m.y() * 1e3, r.contact_struck_m.z() * 1e3, struck_name, struck_predicted.x() * 1e3,
              struck_predicted.y() * 1e3, struck_predicted.z() * 1e3);
  if (r.contact_left_m.allFinite()) {
    std::printf("       left   (%.3f, %.3f, %.4f) mm, predicted %s (%.3f, %.3f, %.4f) mm\n", r.contact_left_m.x() * 1e3,
                r.contact_left_m.y() * 1e3, r.contact_left_m.z() * 1e3, left_name, left_predicted.x() * 1e3,
                left_predicted.y() * 1e3, left_predicted.z() * 1e3);
  }
  std::printf("       zdot %.5f -> %.5f m/s (predicted %.5f -> %.5f)\n", r.zdot_before_m_per_s, r.zdot_after_m_per_s,
              p.zdot_before_m_per_s, p.zdot_after_m_per_s);
  std::printf("       max penetration %.3g m, lift-off %s", r.max_penetration_m, r.liftoff ? "yes" : "no");
  if (r.liftoff) std::printf(" at %.4f ms", r.liftoff_time_s * 1e3);
  if (r.second_impact) std::printf(", second impact at %.4f ms: %.2f N s", r.second_impact_time_s * 1e3, r.second_impulse_Ns);
  std::printf("\n");
  std::printf("vertical momentum jump Delta p_z\n");
  std::printf("  simulated            %12.4f N s   (contact impulses: %.4f N s)\n", r.impulse_Ns,
              r.impulse_from_contacts_Ns);
  print_form("exact, v held", p.impulse.exact_Ns, r.impulse_Ns);
  print_form("thesis as printed", p.impulse.thesis_Ns, r.impulse_Ns);
  print_form("small angle", p.impulse.small_angle_Ns, r.impulse_Ns);
  if (r.thin_disc_prediction) print_form("thin disc, exact", r.thin_disc_prediction->impulse.exact_Ns, r.impulse_Ns);
}

void print_inertial(const SimulationResult& r) {
  const InertialOutcome& o = *r.inertial;
  const double v = r.simulated_wheel.speed_m_per_s;
  std::printf("inertial: wheel load %.4g N + weight = static contact force %.4g N; horizontal speed %s", o.wheel_load_N,
              o.static_load_N, to_string(o.horizontal));
  if (o.horizontal == HorizontalMotion::free) std::printf(" (carrier %.4g kg)", o.carrier_mass_kg);
  std::printf("; spin %s; flat approach %.3g m; contact %s\n", o.spinning ? "free (friction)" : "locked",
              o.flat_approach_m, o.compliant ? "compliant" : "rigid");
  std::printf("phases\n");
  for (const ContactPhase& p : o.phases) {
    std::printf("  %-8s t %9.4f .. %9.4f ms   x %9.3f .. %9.3f mm\n", p.in_contact ? "contact" : "FLIGHT",
                p.start_time_s * 1e3, p.end_time_s * 1e3, p.start_x_m * 1e3, p.end_x_m * 1e3);
  }
  for (const Flight& f : o.flights) {
    std::printf("  flight: lift-off at x = %.3f mm (zdot %.4f m/s), %s, %.4f ms long, apex %.4f mm above lift-off, "
                "%.4f mm above the kinematic path\n",
                f.liftoff_x_m * 1e3, f.liftoff_zdot_m_per_s, f.landed ? "landed" : "still flying at the end",
                f.duration_s * 1e3, f.apex_height_m * 1e3, f.max_clearance_m * 1e3);
  }
  std::printf("impacts (momentum jumps%s)\n", o.compliant ? " = impulse of each force pulse above the static load" : "");
  for (std::size_t i = 0; i < r.trajectory.impacts.size(); ++i) {
    const ImpactEvent& e = r.trajectory.impacts[i];
    std::printf("  %s t %9.4f ms  x %9.3f mm  jump %10.3f N s  horizontal impulse %9.3f N s%s", 
                static_cast<int>(i) == o.joint_impact_index ? "joint" : "     ", e.time_s * 1e3, e.wheel_x_m * 1e3,
                e.momentum_jump_Ns, e.horizontal_impulse_Ns, e.landing ? "  (landing)" : "");
    if (o.compliant) std::printf("  peak %.4g N", e.peak_force_N);
    std::printf("\n");
  }
  std::printf("total vertical impulse %.3f N s (kinematic jump %.3f N s)\n", o.total_impulse_Ns,
              r.prediction.impulse.exact_Ns);
  std::printf("kinematic path %s: max deviation %.4g mm at x = %.3f mm (rise %.4g mm, sink %.4g mm)%s\n",
              o.followed_kinematic_path ? "followed" : "NOT followed", o.max_deviation_m * 1e3, o.max_deviation_x_m * 1e3,
              o.max_rise_m * 1e3, o.max_sink_m * 1e3, o.ended_in_flight ? "; run ended in flight" : "");
  if (o.ended_in_flight) {
    // The total above then lacks the landing: say how to see it.
    std::printf("  the run ended before the landing: lengthen joint.length and sim.run_out_time (< 0.4 joint.length / v),\n"
                "  e.g. --set joint.length=3 --set sim.run_out_time=0.02 at 50 m/s\n");
  }
  if (std::isfinite(o.pivot_liftoff_speed_m_per_s)) {
    std::printf("lift-off model: pivot at the joint, radius %.5f rad from vertical: leaves it above %.3f m/s (v = %.3f)\n",
                o.pivot_angle_rad, o.pivot_liftoff_speed_m_per_s, v);
  }
  if (std::isfinite(o.entry_kink_liftoff_speed_m_per_s)) {
    std::printf("lift-off model: entry kink of the dip leaves above %.3f m/s\n", o.entry_kink_liftoff_speed_m_per_s);
  }
  std::printf("lift-off predicted %s, simulated %s\n", o.liftoff_predicted ? "yes" : "no", o.flights.empty() ? "no" : "yes");
  std::printf("horizontal velocity at the joint impact %.5f -> %.5f m/s, horizontal contact impulse %.3f N s\n",
              o.xdot_before_m_per_s, o.xdot_after_m_per_s, o.joint_horizontal_impulse_Ns);
  if (o.compliant && !r.impact_found) {
    std::printf("compliant contact k = %.4g N/m, c = %.4g N s/m: no impact at the joint, so no peak force\n",
                o.contact_stiffness_N_per_m, o.contact_damping_N_s_per_m);
  } else if (o.compliant) {
    std::printf("compliant contact k = %.4g N/m, c = %.4g N s/m: peak vertical force %.5g N at x = %.3f mm\n"
                "  P1 for a rigid track P0 + dv sqrt(k M): dv = beta v %.5g N (%+.2f %%), dv = Delta p / M %.5g N "
                "(%+.2f %%)\n",
                o.contact_stiffness_N_per_m, o.contact_damping_N_s_per_m, o.peak_force_N, o.peak_force_x_m * 1e3,
                o.rigid_track_p1_beta_v_N, 100.0 * (o.peak_force_N / o.rigid_track_p1_beta_v_N - 1.0),
                o.rigid_track_p1_N, 100.0 * (o.peak_force_N / o.rigid_track_p1_N - 1.0));
  }
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Bullet (double precision) simulation of the wheel crossing the joint: an implicit cylinder\n"
      "carried at constant horizontal speed, pressed onto two rail meshes. Measures the vertical\n"
      "momentum jump M (zdot+ - zdot-) at the impact and compares it with the analytic forms.\n"
      "A thin disc (wheel.width = 0) is simulated as a cylinder of width 2 sim.disc_half_width and\n"
      "compared with that cylinder's governing slice. A scene with a [render] section is also drawn\n"
      "off-screen, as `railjoint render` does, into --render-out.");
  cmd->add_option("scene", options->scene_path,
                  "Scene file (TOML): [joint] and [wheel] as for `analytic`, and optionally [sim], SI units:\n"
                  "  mode = \"kinematic\" | \"inertial\", time_step [s], refined_time_step [s], refine_distance [m],\n"
                  "  refine_hold [s] (absent: 2e-5 kinematic, 5e-5 inertial), margin [m], contact_breaking_threshold [m],\n"
                  "  contact_processing_threshold [m], split_impulse_threshold [m], slop [m],\n"
                  "  solver_iterations, hard_contacts (bool), preload [N] (kinematic only; absent: 2 M v^2 / R\n"
                  "  when the jump is on landing, else 100 kN), friction, restitution, internal_edge_fix (bool),\n"
                  "  disc_half_width [m], approach_distance [m], run_out_time [s].\n"
                  "  Inertial mode (the wheel pressed on only by its weight and the static wheel load, free to\n"
                  "  leave the rail): wheel_load [N] (default 112.5e3, thesis table 6.1), horizontal = \"held\" |\n"
                  "  \"free\", carrier_mass [kg] (free: mass moving with the wheel; absent: wheel_load / g),\n"
                  "  friction > 0 lets the wheel spin with radius_of_gyration [m] (absent: R / sqrt 2, solid\n"
                  "  disc), restitution, flat_approach [m] (level rail before the dip: the wheel crosses the\n"
                  "  dip's entry kink), contact_stiffness [N/m] and contact_damping [N s/m] (compliant contact:\n"
                  "  finite impact forces; absent: rigid). Flights need room: lengthen joint.length and\n"
                  "  run_out_time (0.4 joint.length / v at most).")
      ->required();
  cmd->add_option("--set", options->overrides, "Override a scene key: section.key=value (repeatable), e.g. sim.time_step=5e-5");
  cmd->add_flag("--json", options->json,
                "Print one JSON object (SI units): analytic (as `analytic --json`), analytic_as_simulated (the\n"
                "wheel Bullet holds, which error is against), sim, error (relative, signed)");
  cmd->add_option("--csv", options->csv_path,
                  "Write the time series as CSV: t, x, z, zdot, contact count, summed vertical contact impulse,\n"
                  "xdot, vertical contact force (impulse / step), the kinematic centre height at x, spin rate");
  CLI::Option* render_out = cmd->add_option("--render-out", options->render_dir,
                  "Folder for the frames when the scene has a [render] section (created; default out/render).\n"
                  "Without [render] nothing is drawn and no GL context is made; `railjoint render` draws any scene");
  cmd->callback([options, render_out] {
    const Scene scene = load_scene(options->scene_path, options->overrides);
    if (!scene.render && render_out->count() > 0) {
      throw InputError(scene.file, "--render-out",
                       "the scene has no [render] section, so simulate draws nothing; add one, or use `railjoint render`");
    }
    // Checked before the run: a bad [render] or folder should cost no simulation.
    // A build without OSMesa still simulates a scene that asks for frames,
    // and says, once, on stderr, that it draws none (`render` fails instead:
    // drawing is all it does).
    const bool draw = scene.render.has_value() && rendering_available();
    if (scene.render && !draw) {
      std::fprintf(stderr, "railjoint: warning: %s: [render] ignored: this build has no OSMesa, so nothing is drawn\n",
                   scene.file.c_str());
    }
    if (draw) prepare_rendering(scene, *scene.render, options->render_dir, "--render-out");
    SimulationResult result;
    try {
      result = simulate_crossing(scene.joint, scene.wheel, scene.sim);
    } catch (const ParameterError& error) {
      throw InputError(scene.file, error.key(), error.what());
    }
    if (!options->csv_path.empty()) write_csv(scene, result, options->csv_path);
    // Drawn before anything is printed: a window the run cannot fill is an
    // error, and an error leaves no half report behind.
    std::optional<RenderedCrossing> rendered;
    if (draw) {
      rendered = render_simulated_crossing(scene, result, *scene.render, options->render_dir, false);
    }
    if (options->json) {
      std::cout << result_json(result).dump(2) << '\n';
    } else {
      print_summary(scene, result);
      if (result.inertial) print_inertial(result);
    }
    // With --json stdout holds the one JSON object: the render report goes to stderr.
    if (rendered) {
      std::fflush(stdout);
      print_render_report(*rendered, options->json ? stderr : stdout);
    }
    // The report above stays for inspection, but a run that measured nothing
    // must not pass for a result in a script.
    if (!result.impact_found) {
      std::fflush(stdout);
      throw std::runtime_error(scene.file + ": the simulation found no impact at the joint (for example a time "
                               "step too coarse to resolve it, or a contact so soft or damped that no jump stands "
                               "out; see `railjoint study stability`)");
    }
    if (!result.inertial && !result.verdict.ok) {
      std::fflush(stdout);
      throw std::runtime_error(scene.file + ": the simulation cannot vouch for its jump: " + result.verdict.reason);
    }
  });
}

}  // namespace railjoint::cli
