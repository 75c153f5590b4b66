#pragma once
// A model a sweep runs on every case ("analytic", "simulate", ...): its
// columns in results.csv and how it fills them. Adding a model is a file
// that returns a CaseModel, declared in case_models.h and listed in its .cpp.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "models/impact_prediction.h"
#include "scenes/report/csv_row.h"
#include "scenes/scene.h"

namespace railjoint {

/// How a case came out, mildest first: a row's verdict is its models' worst.
enum class CaseVerdict {
  ok,         ///< every model gave its numbers
  suspect,    ///< a simulation that cannot vouch for its jump (sim/self_check.h)
  no_impact,  ///< a simulation that found no impact
  failed,     ///< a model threw something other than bad input (a bug, or out of memory)
  rejected,   ///< the scene or a model refused the case's input, with the key and the range
};

const char* to_string(CaseVerdict verdict);

/// One case as the models see it: the scene (base + the case's values, its
/// keys checked) and its kinematic prediction, the model check of load_scene,
/// made on first use and shared by the models that need it.
class CaseInput {
 public:
  explicit CaseInput(const Scene& scene) : scene_(scene) {}
  const Scene& scene() const { return scene_; }
  /// predict_impact of the scene's joint and wheel (the scene's own when it
  /// was read with SceneCheck::model); throws InputError for a case outside
  /// the kinematic model (as load_scene does), every time it is asked.
  const ImpactPrediction& prediction() const;
  /// The crossing a simulating model runs, checked and built once per case
  /// from that prediction (as load_scene's SceneCheck::simulation); throws
  /// InputError naming the key, every time it is asked.
  const std::shared_ptr<const CrossingModel>& crossing() const;

 private:
  const Scene& scene_;
  mutable std::optional<ImpactPrediction> prediction_;
  mutable std::shared_ptr<const CrossingModel> crossing_;
};

struct ModelOutcome {
  CaseVerdict verdict = CaseVerdict::ok;
  std::string message;  ///< why, when not ok
};

struct CaseModel {
  std::string name;                  ///< as `run` names it
  std::vector<std::string> columns;  ///< "name.column_unit", in order
  /// Appends exactly columns.size() cells. Throws InputError for input the
  /// model refuses (the runner then leaves its cells empty and
  /// the row says why); must not touch shared mutable state (cases run on many threads).
  std::function<ModelOutcome(const CaseInput&, CsvRow&)> run;
};

}  // namespace railjoint
