#include "scenes/sweeps/case_models.h"

#include <algorithm>
#include <cassert>

namespace railjoint {

namespace {

// Every model sweep files may name in `run`.
std::vector<CaseModel> registered_case_models() {
  return {analytic_case_model(), simulate_case_model(), pressure_case_model(), forces_case_model()};
}

}  // namespace

std::vector<std::string> case_model_names() {
  std::vector<std::string> names;
  for (const CaseModel& model : registered_case_models()) names.push_back(model.name);
  return names;
}

std::vector<CaseModel> case_models(const std::vector<std::string>& names) {
  const std::vector<CaseModel> all = registered_case_models();
  std::vector<CaseModel> chosen;
  for (const std::string& name : names) {
    const auto found = std::find_if(all.begin(), all.end(), [&](const CaseModel& m) { return m.name == name; });
    assert(found != all.end() && "sweep_file.cpp checks `run` against case_model_names()");
    chosen.push_back(*found);
  }
  return chosen;
}

}  // namespace railjoint
