#pragma once
// The models a sweep can run, by name.

#include <string>
#include <vector>

#include "scenes/sweeps/case_model.h"

namespace railjoint {

/// Every model sweep files may name in `run`.
std::vector<CaseModel> registered_case_models();

/// Their names, for messages and for reading `run`.
std::vector<std::string> case_model_names();

/// The models `names` asks for, in that order (names must be registered).
std::vector<CaseModel> case_models(const std::vector<std::string>& names);

}  // namespace railjoint
