#pragma once
// One run of the local model (thesis chapters 5-6) for a loaded scene: the
// inputs as the scene resolves them, the traversal and its summary. Shared by
// the `pressure` command, its reports and the renderer.

#include <optional>
#include <string>
#include <vector>

#include "models/hertz_contact.h"
#include "models/pressure_traversal.h"
#include "models/rail_end_contact.h"
#include "models/rail_end_fields.h"
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

/// The load a solved crossing takes from the same scene's force run
/// (contact_patch.normal_force = "forces"): the contact force against the
/// wheel's position, so that the rail end sees P1 where the wheel was over it.
struct ForceRunLoad {
  std::string track;         ///< the run's [track] model ("rigid", "lumped", "discrete")
  double static_N = 0.0;     ///< P0 = sim.wheel_load + M g [N]
  double p1_N = 0.0;         ///< the run's largest contact force [N]
  double p1_x_m = 0.0;       ///< the wheel's centre x then [m]
  double p1_time_s = 0.0;    ///< on the run's clock [s]
  bool vouched = true;       ///< the force run's own verdict
  std::string verdict;       ///< why not, when not vouched
  std::vector<double> x_m;      ///< wheel centre x per recorded step (rising) [m]
  std::vector<double> force_N;  ///< total vertical contact force then (the --csv's contact_force_z_N) [N]

  /// N at wheel position x: linear between the recorded steps. Throws
  /// InputError (sim.run_out_time / sim.approach_distance) outside the run.
  double force_at(double x_m) const;
};

/// A shape = "solved" run: the crossing, and the force run that loaded it.
struct SolvedContactRun {
  RailEndCrossing crossing;
  std::optional<ForceRunLoad> load;  ///< normal_force = "forces"; empty: the static normal_force
  double window_over_axes = 0.0;     ///< the grid's sides over Hertz's full axes at the sizing load [-]
  /// The window given or by default, where the patch reached its border and
  /// the window grew (contact_patch.window_over_axes not given); empty: it held.
  std::optional<double> window_grown_from;
  /// Every step's field, when asked for (`pressure --frames`); else empty.
  std::vector<RailEndField> fields;
};

/// The solved crossing for the scene; InputError names the scene file.
/// `keep_fields`: the run keeps every step's field (`pressure --frames`).
SolvedContactRun run_solved_contact(const Scene& scene, bool keep_fields = false);

}  // namespace railjoint
