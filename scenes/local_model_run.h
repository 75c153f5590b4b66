#pragma once
// One run of the local model (thesis chapters 5-6) for a loaded scene: the
// inputs as the scene resolves them, the traversal and its summary. Shared by
// the `pressure` command, its reports and the renderer.

#include <optional>
#include <vector>

#include "models/hertz_contact.h"
#include "models/pressure_traversal.h"
#include "scenes/scene.h"

namespace railjoint {

struct LocalModelRun {
  PressureInputs inputs;
  std::vector<PressureState> traversal;
  PressureSummary summary;
  std::optional<HertzEllipse> hertz_size;  ///< the Hertz ellipse when contact_patch.size = "hertz"
};

/// Throws InputError (file, key) for a scene the local model cannot describe.
LocalModelRun run_local_model(const Scene& scene);

/// The same model for another junction angle (the figures' families of curves);
/// throws InputError when the gap is too wide for the patch at that angle.
LocalModelRun run_local_model_at(const PressureInputs& inputs, double theta_deg);

}  // namespace railjoint
