// `railjoint simulate`: the Bullet crossing of one scene, its measured
// vertical momentum jump and the error against the three analytic forms.

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/parameter_error.h"
#include "scenes/cli/commands.h"
#include "scenes/input_error.h"
#include "scenes/prediction_json.h"
#include "scenes/scene_file.h"
#include "sim/simulate_crossing.h"

namespace railjoint::cli {

namespace {

struct SimulateOptions {
  std::string scene_path;
  std::vector<std::string> overrides;
  bool json = false;
  std::string csv_path;
};

double relative_error(double simulated, double form) { return (simulated - form) / form; }

nlohmann::json vector_json(const Eigen::Vector3d& v) {
  if (!v.allFinite()) return nullptr;
  return nlohmann::json::array({v.x(), v.y(), v.z()});
}

nlohmann::json result_json(const SimulationResult& r) {
  nlohmann::json out;
  out["analytic"] = prediction_to_json(r.prediction);
  if (r.thin_disc_prediction) out["analytic_thin_disc"] = prediction_to_json(*r.thin_disc_prediction);
  nlohmann::json sim;
  sim["impact_found"] = r.impact_found;
  sim["impulse"] = r.impulse_Ns;
  sim["impulse_from_contacts"] = r.impulse_from_contacts_Ns;
  sim["impact_time"] = r.impact_time_s;
  sim["impact_x"] = r.impact_x_m;
  sim["zdot_before"] = r.zdot_before_m_per_s;
  sim["zdot_after"] = r.zdot_after_m_per_s;
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
  out["sim"] = sim;
  const ImpulseForms& f = r.prediction.impulse;
  out["error"] = {{"exact", relative_error(r.impulse_Ns, f.exact_Ns)},
                  {"thesis", relative_error(r.impulse_Ns, f.thesis_Ns)},
                  {"small_angle", relative_error(r.impulse_Ns, f.small_angle_Ns)}};
  if (r.thin_disc_prediction) {
    out["error_vs_thin_disc"] = {{"exact", relative_error(r.impulse_Ns, r.thin_disc_prediction->impulse.exact_Ns)}};
  }
  return out;
}

void write_csv(const SimulationResult& r, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw InputError(path, "--csv", "cannot write this file (does its folder exist?)");
  out.precision(12);
  out << "t_s,x_m,z_m,zdot_m_per_s,contacts,contact_impulse_z_Ns\n";
  for (const WheelSample& s : r.trajectory.samples) {
    double impulse_z = 0;
    for (const ContactSample& c : s.contacts) impulse_z += c.normal_impulse_Ns * c.normal.z();
    out << s.time_s << ',' << s.centre_m.x() << ',' << s.centre_m.z() << ',' << s.velocity_m_per_s.z() << ','
        << s.contacts.size() << ',' << impulse_z << '\n';
  }
}

void print_form(const char* name, double form, double simulated) {
  std::printf("  %-20s %12.4f N s   sim error %+.4f %%\n", name, form, 100.0 * relative_error(simulated, form));
}

void print_summary(const Scene& scene, const SimulationResult& r) {
  const ImpactPrediction& p = r.prediction;
  std::printf("scene  %s (%s)\n", scene.name.c_str(), scene.file.c_str());
  std::printf("sim    Bullet (double), mode %s, dt %.3g s refined to %.3g s, margin %.3g m, slop %.3g m, preload %.4g N\n",
              to_string(scene.sim.mode), scene.sim.time_step_s, scene.sim.refined_time_step_s, scene.sim.margin_m,
              scene.sim.slop_m, r.preload_N);
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

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Bullet (double precision) simulation of the wheel crossing the joint: an implicit cylinder\n"
      "carried at constant horizontal speed, pressed onto two rail meshes. Measures the vertical\n"
      "momentum jump M (zdot+ - zdot-) at the impact and compares it with the analytic forms.\n"
      "A thin disc (wheel.width = 0) is simulated as a cylinder of width 2 sim.disc_half_width and\n"
      "compared with that cylinder's governing slice.");
  cmd->add_option("scene", options->scene_path,
                  "Scene file (TOML): [joint] and [wheel] as for `analytic`, and optionally [sim], SI units:\n"
                  "  mode = \"kinematic\", time_step [s], refined_time_step [s], refine_distance [m],\n"
                  "  refine_hold [s], margin [m], contact_breaking_threshold [m],\n"
                  "  contact_processing_threshold [m], split_impulse_threshold [m], slop [m],\n"
                  "  solver_iterations, hard_contacts (bool), preload [N] (absent: 2 M v^2 / R when the jump\n"
                  "  is on landing, else 100 kN), friction, restitution, internal_edge_fix (bool),\n"
                  "  disc_half_width [m], approach_distance [m], run_out_time [s]")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--set", options->overrides, "Override a scene key: section.key=value (repeatable), e.g. sim.time_step=5e-5");
  cmd->add_flag("--json", options->json, "Print one JSON object (SI units): analytic, sim, error (relative, signed)");
  cmd->add_option("--csv", options->csv_path,
                  "Write the time series (t, x, z, zdot, contact count, summed vertical contact impulse) as CSV");
  cmd->callback([options] {
    const Scene scene = load_scene(options->scene_path, options->overrides);
    SimulationResult result;
    try {
      result = simulate_crossing(scene.joint, scene.wheel, scene.sim);
    } catch (const ParameterError& error) {
      throw InputError(scene.file, error.key(), error.what());
    }
    if (!options->csv_path.empty()) write_csv(result, options->csv_path);
    if (options->json) {
      std::cout << result_json(result).dump(2) << '\n';
    } else {
      print_summary(scene, result);
    }
  });
}

}  // namespace railjoint::cli
