#pragma once
// The [contact_patch] section of a scene file: the local model of thesis
// chapters 5-6 (models/local_model_settings.h). Optional in every scene, so
// one file describes both the global and the local analysis; theta and the
// gap come from [joint], the speed and the wheel radius from [wheel].
//   shape = "ellipse" | "polygon" | "rectangle" | "solved"   (default "ellipse")
//   size = "given" | "hertz"                       (default "given")
//   length [m] = 0.016, width [m] = 0.012          (size = "given")
//   vertices = 100                                 (shape = "polygon")
//   normal_force [N] = 112.5e3, steps = 1000
//   normal_force = "forces" (shape = "solved"): the load at each step is the
//   contact force of the same scene's force run ([sim] mode = "inertial",
//   [contact] law = "hertz", [track]) where the wheel is (local_model_run.h)
//   crown_radius [m] = 0.3, youngs_modulus [Pa] = 210e9, poisson_ratio = 0.3  (size = "hertz")
//   shape = "solved": the boundary-element contact on the surfaces of [joint]
//   and [wheel] (models/rail_end_contact.h), steps = 100,
//   yield_pressure [Pa] (absent: elastic; R260: 1.15e9, the shakedown limit
//   4 k, README), height_mismatch [m] = 0 (outgoing end above the incoming),
//   cells_x = 128, cells_y = 96, window_over_axes = 2.5 (the grid's sides over
//   Hertz's full axes; absent, it grows where a patch reaches the border),
//   youngs_modulus, poisson_ratio.
// A key that would change nothing in the chosen shape or size is an error.

#include "models/local_model_settings.h"
#include "models/pressure_traversal.h"
#include "scenes/section_reader.h"
#include "sim/setting_checks.h"

namespace railjoint {

struct Scene;

/// The most work a pressure run may take: a polygon's vertices x steps.
inline constexpr double kMaxPolygonVertexSteps = 1e9;

/// Reads the section; a key that changes nothing with the chosen shape or
/// size blames the one of the two the user typed last (`origins`).
ContactPatchSettings read_contact_patch_section(SectionReader& in, const KeyOrigins& origins);

/// The local model's inputs for a loaded scene; a combination the model
/// cannot describe (no gap, a gap wider than the patch, a patch wider than
/// the rail head) throws InputError naming the scene file and the key.
PressureInputs local_model_inputs_of(const Scene& scene);

}  // namespace railjoint
