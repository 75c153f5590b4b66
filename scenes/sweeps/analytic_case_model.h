#pragma once
// The kinematic model on every case (`railjoint analytic`): scenario,
// transition value y_t, governing slice, contact point A, and the jump in
// the three forms of models/DESIGN.md "Three forms of every analytic impulse". No Bullet.

#include "scenes/sweeps/case_model.h"

namespace railjoint {

CaseModel analytic_case_model();

}  // namespace railjoint
