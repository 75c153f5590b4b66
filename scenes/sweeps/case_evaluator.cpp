#include "scenes/sweeps/case_evaluator.h"

#include <chrono>
#include <exception>

#include "models/input_error.h"

namespace railjoint {

namespace {

// A row's message: each model's reason, "; "-separated.
void add_reason(std::string& message, const std::string& reason) {
  if (reason.empty()) return;
  if (!message.empty()) message += "; ";
  message += reason;
}

}  // namespace

CaseEvaluator::CaseEvaluator(const SweepFile& sweep, std::vector<CaseModel> models)
    : file_(sweep.file), base_(parse_scene_tree(sweep.base_text, sweep.base_scene)), grid_(sweep),
      models_(std::move(models)) {
  for (const CaseModel& model : models_) model_cells_ += model.columns.size();
  // A key no scene has would reject every case: refuse the sweep file instead.
  // Each axis alone on the base, with its first value (or its range's start):
  // only an unknown key or section is the sweep file's fault; any other
  // refusal may be one case's and becomes its row.
  for (const SweepAxis& axis : sweep.axes) {
    const SceneValue first = axis.values.empty() ? SceneValue(axis.from) : axis.values.front();
    try {
      read_scene_tree(base_, file_, {{axis.section, axis.key, first}}, SceneCheck::keys_only);
    } catch (const InputError& error) {
      const std::string text = error.what();
      const bool unknown = (error.key() == axis.name() && text.find("unknown key") != std::string::npos) ||
                           (error.key() == axis.section && text.find("unknown section") != std::string::npos);
      if (unknown) {
        throw InputError(file_, "axes." + axis.name(), "is not a scene key (`railjoint simulate --help` lists them)");
      }
    }
  }
}

std::string CaseEvaluator::header() const {
  CsvRow row;
  row.text("case");
  for (const std::string& key : grid_.keys()) row.text(key);
  row.text("verdict");
  row.text("message");
  for (const CaseModel& model : models_) {
    for (const std::string& column : model.columns) row.text(column);
  }
  row.text("wall_ms");
  return row.str();
}

CaseVerdict CaseEvaluator::append_row(std::uint64_t index, CaseScratch& scratch, CsvRow& row) const {
  const auto start = std::chrono::steady_clock::now();
  grid_.overrides(index, scratch.overrides);
  row.integer(static_cast<long long>(index));
  for (const SceneOverride& o : scratch.overrides) row.value(o.value);

  CaseVerdict verdict = CaseVerdict::ok;
  std::string message;
  CsvRow& cells = scratch.model_cells;
  cells.truncate(0, 0);
  try {
    // The keys here; each model checks what its command checks: the kinematic
    // model's limits when a model first asks for the prediction (CaseInput,
    // load_scene's SceneCheck::model), the local model its own (`pressure`).
    Scene scene = read_scene_tree(base_, file_, scratch.overrides, SceneCheck::keys_only);
    // The rails `simulate` and `analytic` derive for this case when the
    // scene gives no joint.length: one rule for every command and the
    // sweep (scene_file.h).
    derive_minimum_rail_length(scene);
    derive_simulated_rail_length(scene);
    const CaseInput input(scene);
    for (const CaseModel& model : models_) {
      const std::size_t size = cells.size();
      const std::size_t count = cells.cells();
      ModelOutcome outcome;
      try {
        outcome = model.run(input, cells);
      } catch (const InputError& error) {
        // The model knows the key, not the file: the case's values come from the sweep file.
        outcome = {CaseVerdict::rejected,
                   model.name + ": " + (error.file().empty() ? error.in_file(file_).what() : error.what())};
      } catch (const std::exception& error) {
        outcome = {CaseVerdict::failed, model.name + ": " + error.what()};
      }
      if (outcome.verdict == CaseVerdict::rejected || outcome.verdict == CaseVerdict::failed) {
        cells.truncate(size, count);
        cells.empty(model.columns.size());
      }
      verdict = std::max(verdict, outcome.verdict);
      add_reason(message, outcome.message);
    }
  } catch (const InputError& error) {
    verdict = CaseVerdict::rejected;
    message = error.what();
    cells.truncate(0, 0);
    cells.empty(model_cells_);
  }
  row.text(to_string(verdict));
  row.text(message);
  row.append(cells);
  const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  row.number(wall_ms, 4);
  row.end_line();
  return verdict;
}

}  // namespace railjoint
