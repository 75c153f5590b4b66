#pragma once
// What a scene file says about the local model (its [contact_patch] section)
// and how it meets the global model's description of the same joint: theta
// and g from [joint], v and the wheel radius from [wheel]. One scene file
// thereby describes both analyses.

#include "models/contact_patch.h"
#include "models/hertz_contact.h"
#include "models/parameters.h"
#include "models/pressure_traversal.h"
#include "models/rail_end_contact.h"

namespace railjoint {

/// How the patch gets its size: as given (the thesis: predetermined), or
/// from Hertz theory for the wheel on the rail head (its section 7.2.2).
enum class PatchSize { given, hertz };

struct ContactPatchSettings {
  ContactPatch patch;               ///< shape; length and width used when size = given
  PatchSize size = PatchSize::given;
  double normal_force_N = 112.5e3;  ///< N (table 6.1) [N]
  /// normal_force = "forces" (shape = "solved" only): the load at each step
  /// is the same scene's force run's contact force N(x) where the wheel is,
  /// not normal_force_N (scenes/local_model_run.h).
  bool load_from_force_run = false;
  int steps = 1000;                 ///< positions over the traversal (table 6.1)
  HertzMaterial hertz;              ///< used when size = hertz
  /// shape = "solved": the patch from the boundary-element contact of the
  /// wheel on the two rail ends (rail_end_contact.h), not prescribed.
  bool solved = false;
  RailEndContactSettings solved_contact;  ///< used when solved
  /// contact_patch.window_over_axes not given: a patch that reaches the
  /// grid's border grows the window and is solved again (local_model_run.h).
  bool grow_window = true;
};

/// The local model's inputs for this joint and wheel: a Hertz-sized patch
/// when asked for (a prescribed patch: not for shape = "solved"). Throws InputError (with the scene key) for a
/// combination the model cannot describe (see check_pressure_inputs).
PressureInputs local_model_inputs(const ContactPatchSettings& settings, const JointParams& joint,
                                  const WheelParams& wheel);

}  // namespace railjoint
