#include "scenes/local_model_run.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "models/normal_contact_solver.h"
#include "scenes/contact_patch_section.h"
#include "scenes/scene_file.h"
#include "sim/force_outcome.h"
#include "sim/simulate_crossing.h"
#include "support/input_error.h"

namespace railjoint {

LocalModelRun run_local_model(const Scene& scene) {
  LocalModelRun run;
  run.inputs = local_model_inputs_of(scene);
  run.traversal = pressure_traversal(run.inputs);
  run.summary = summarize_pressure(run.inputs, run.traversal);
  if (scene.contact_patch.size == PatchSize::hertz) {
    run.hertz_size = wheel_on_rail_hertz_ellipse(scene.wheel.radius_m, scene.contact_patch.hertz,
                                                 scene.contact_patch.normal_force_N);
  }
  return run;
}

LocalModelRun run_local_model_at(const PressureInputs& inputs, double theta_deg) {
  LocalModelRun run;
  run.inputs = inputs;
  run.inputs.gap.theta_rad = theta_deg * std::numbers::pi / 180.0;
  check_pressure_inputs(run.inputs);
  run.traversal = pressure_traversal(run.inputs);
  run.summary = summarize_pressure(run.inputs, run.traversal);
  return run;
}

double ForceRunLoad::force_at(double x) const {
  if (x < x_m.front()) {
    throw InputError("sim.approach_distance",
                     "the force run starts with the wheel at x = " + std::to_string(x_m.front()) +
                         " m, after the solved traversal's first position " + std::to_string(x) +
                         " m: start the run further back");
  }
  if (x > x_m.back()) {
    throw InputError("sim.run_out_time", "the force run ends with the wheel at x = " + std::to_string(x_m.back()) +
                                             " m, before the solved traversal's last position " + std::to_string(x) +
                                             " m: run it longer");
  }
  const auto above = std::upper_bound(x_m.begin(), x_m.end(), x);
  if (above == x_m.end()) return force_N.back();
  const std::size_t k = static_cast<std::size_t>(above - x_m.begin());  // x_m[k-1] <= x < x_m[k]
  const double w = (x - x_m[k - 1]) / (x_m[k] - x_m[k - 1]);
  return (1.0 - w) * force_N[k - 1] + w * force_N[k];
}

namespace {

// The scene's force run and its N(x). InputError under
// contact_patch.normal_force when the scene has none.
ForceRunLoad force_run_load(const Scene& scene) {
  const InertialSettings* inertial = scene.sim.inertial();
  if (inertial == nullptr || inertial->elastic() == nullptr) {
    throw InputError(scene.file, "contact_patch.normal_force",
                     "= \"forces\" takes the load from the scene's force run, and this scene has none: give [sim] "
                     "mode = \"inertial\" and [contact] law = \"hertz\" (with [track] model = \"rigid\", \"lumped\" "
                     "or \"discrete\"; scenes/forces/lumped_track.toml), or a number [N] in (0, 1e8]");
  }
  Scene simulated = scene;
  check_for_simulation(simulated);
  const SimulationResult result = simulate_crossing(simulated.crossing);
  const ForceOutcome& forces = *result.inertial()->forces;
  ForceRunLoad load;
  load.track = track_model_name(forces.track_model);
  load.static_N = forces.static_N;
  load.p1_N = forces.p1_N;
  load.p1_time_s = forces.p1_time_s;
  load.p1_x_m = result.inertial()->peak_force_x_m;
  load.vouched = result.verdict.ok;
  load.verdict = result.verdict.reason;
  const std::vector<WheelSample>& samples = result.trajectory.samples;
  load.x_m.reserve(samples.size());
  load.force_N.reserve(samples.size());
  for (std::size_t k = 0; k < samples.size() && k < forces.contact_force_N.size(); ++k) {
    // x rises step by step (the carrier moves the wheel on at v > 0): a
    // sample that does not advance adds nothing to N(x).
    if (!load.x_m.empty() && !(samples[k].centre_m.x() > load.x_m.back())) continue;
    load.x_m.push_back(samples[k].centre_m.x());
    load.force_N.push_back(forces.contact_force_N[k]);
  }
  if (load.x_m.size() < 2) throw std::runtime_error(scene.file + ": the force run recorded fewer than 2 positions");
  return load;
}

}  // namespace

SolvedContactRun run_solved_contact(const Scene& scene, bool keep_fields) {
  SolvedContactRun run;
  const ContactPatchSettings& patch = scene.contact_patch;
  if (patch.load_from_force_run) run.load = force_run_load(scene);
  RailEndContactSettings settings = patch.solved_contact;
  // The grid as for the static load P0 the run starts under: the same
  // cells and positions as the static crossing, so the two compare step by
  // step; a patch under P1 is (P1 / P0)^(1/3) wider, which the window of
  // 2.5 Hertz axes holds up to some 10 P0. The window is centred on the
  // wheel's first touching point, so where the wheel bears on both rail
  // ends the other end's patch may lie past it. Where the window was not
  // given, one the patch reaches grows by kWindowGrowth, the cells with it,
  // and the crossing is solved again; the report says so.
  constexpr double kWindowGrowth = 1.4;
  const double sizing_N = run.load ? run.load->static_N : patch.normal_force_N;
  const NormalForceAt force = run.load ? NormalForceAt([&load = *run.load](double x) { return load.force_at(x); })
                                       : NormalForceAt([n = patch.normal_force_N](double) { return n; });
  for (;;) {
    // The fields of an attempt the border ends are not the crossing's.
    run.fields.clear();
    RailEndFieldObserver keep;
    if (keep_fields) keep = [&run](const RailEndField& field) { run.fields.push_back(field); };
    try {
      run.crossing = rail_end_crossing_observed(scene.joint, scene.wheel, settings, force, sizing_N, patch.steps, keep);
      run.window_over_axes = settings.window_over_axes;
      return run;
    } catch (const PatchReachesBorder& error) {
      // Two decimals: the report's window reads as typed (3.5, 4.9).
      const double larger = std::round(settings.window_over_axes * kWindowGrowth * 100.0) / 100.0;
      if (!patch.grow_window || larger > kMaxWindowOverAxes) throw error.in_file(scene.file);
      run.window_grown_from = run.window_grown_from.value_or(settings.window_over_axes);
      settings.window_over_axes = larger;
    } catch (const InputError& error) {
      throw error.in_file(scene.file);
    }
  }
}

}  // namespace railjoint
