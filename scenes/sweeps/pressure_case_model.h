#pragma once
// The local model on every case (`railjoint pressure`, thesis ch. 5-6): the
// uniform contact pressure of the patch crossing the end-post gap, its
// largest value and rate of change, and the Hertzian peak (ellipse patches).

#include "scenes/sweeps/case_model.h"

namespace railjoint {

CaseModel pressure_case_model();

}  // namespace railjoint
