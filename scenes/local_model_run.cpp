#include "scenes/local_model_run.h"

#include <algorithm>
#include <numbers>
#include <stdexcept>

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

SolvedContactRun run_solved_contact(const Scene& scene, const RailEndFieldObserver& observe) {
  SolvedContactRun run;
  const ContactPatchSettings& patch = scene.contact_patch;
  if (patch.load_from_force_run) run.load = force_run_load(scene);
  try {
    if (run.load) {
      const ForceRunLoad& load = *run.load;
      // The grid as for the static load P0 the run starts under: the same
      // cells and positions as the static crossing, so the two compare step
      // by step; a patch under P1 is (P1 / P0)^(1/3) wider, which the window
      // of 2.5 Hertz axes holds up to some 10 P0 (the solver refuses, by
      // key, a patch that reaches the border).
      run.crossing = rail_end_crossing_observed(scene.joint, scene.wheel, patch.solved_contact,
                                                [&load](double x) { return load.force_at(x); }, load.static_N,
                                                patch.steps, observe);
    } else {
      const double n = patch.normal_force_N;
      run.crossing = rail_end_crossing_observed(scene.joint, scene.wheel, patch.solved_contact,
                                                [n](double) { return n; }, n, patch.steps, observe);
    }
  } catch (const InputError& error) {
    throw error.in_file(scene.file);
  }
  return run;
}

}  // namespace railjoint
