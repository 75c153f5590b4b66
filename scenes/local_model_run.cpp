#include "scenes/local_model_run.h"

#include <numbers>

#include "scenes/contact_patch_section.h"

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

}  // namespace railjoint
