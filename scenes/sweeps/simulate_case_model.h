#pragma once
// The Bullet crossing on every case (`railjoint simulate`): the measured
// jump, its errors against the three analytic forms of the wheel as
// simulated (a thin disc is a 1 mm cylinder whose inner face governs) and
// against the scene's own thin disc, the run's verdict, the impact position.

#include "scenes/sweeps/case_model.h"

namespace railjoint {

CaseModel simulate_case_model();

}  // namespace railjoint
