#include "models/local_model_settings.h"

#include "support/input_error.h"

namespace railjoint {

PressureInputs local_model_inputs(const ContactPatchSettings& settings, const JointParams& joint,
                                  const WheelParams& wheel) {
  if (settings.solved) {
    throw InputError("contact_patch.shape", "\"solved\" has no prescribed patch: only `railjoint pressure` runs it");
  }
  PressureInputs inputs;
  inputs.patch = settings.patch;
  if (settings.size == PatchSize::hertz) {
    const HertzEllipse ellipse = wheel_on_rail_hertz_ellipse(wheel.radius_m, settings.hertz, settings.normal_force_N);
    inputs.patch.length_m = 2.0 * ellipse.semi_axis_x_m;
    inputs.patch.width_m = 2.0 * ellipse.semi_axis_y_m;
  }
  // The thesis draws the gap as wide as the patch for convenience; in reality
  // the rail head is wider than the patch, and a patch must fit on it.
  if (inputs.patch.width_m > 2.0 * joint.half_width_m) {
    throw InputError(settings.size == PatchSize::hertz ? "contact_patch.crown_radius" : "contact_patch.width",
                         "the contact patch (" + metres_text(inputs.patch.width_m) +
                             " wide) must fit on the rail head (2 joint.half_width = " +
                             metres_text(2.0 * joint.half_width_m) + ")");
  }
  inputs.gap = EndPostGap{joint.gap_m, joint.theta_rad};
  inputs.normal_force_N = settings.normal_force_N;
  inputs.speed_m_per_s = wheel.speed_m_per_s;
  inputs.steps = settings.steps;
  check_pressure_inputs(inputs);
  return inputs;
}

}  // namespace railjoint
