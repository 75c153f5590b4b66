#pragma once
// The models a sweep can run, by name.

#include <string>
#include <vector>

#include "scenes/sweeps/case_model.h"

namespace railjoint {

/// The kinematic model on every case (`railjoint analytic`): scenario,
/// transition value y_t, governing slice, contact point A, and the jump in
/// the three forms of models/DESIGN.md "Three forms of every analytic impulse". No Bullet.
CaseModel analytic_case_model();

/// The Bullet crossing on every case (`railjoint simulate`): the measured
/// jump, its errors against the three analytic forms of the wheel as
/// simulated (a thin disc is a 1 mm cylinder whose inner face governs) and
/// against the scene's own thin disc, the run's verdict, the impact position.
CaseModel simulate_case_model();

/// The local model on every case (`railjoint pressure`, thesis ch. 5-6): the
/// uniform contact pressure of the patch crossing the end-post gap, its
/// largest value and rate of change, and the Hertzian peak (ellipse patches).
CaseModel pressure_case_model();

/// The force run on every case (`railjoint simulate` of a scene with
/// contact.law = "hertz", sim/elastic_crossing_run.h): P1 and P2 and their
/// times, the static load, Jenkins's P1 and P2 for the case's own track, the
/// flights, and the rail-seat and ballast forces where the track records them.
/// A case whose scene is no force run is refused by key.
CaseModel forces_case_model();

/// Every model's name, for messages and for reading `run`.
std::vector<std::string> case_model_names();

/// The models `names` asks for, in that order (names must be registered).
std::vector<CaseModel> case_models(const std::vector<std::string>& names);

}  // namespace railjoint
