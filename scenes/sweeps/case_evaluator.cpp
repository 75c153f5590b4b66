#include "scenes/sweeps/case_evaluator.h"

#include <chrono>
#include <exception>
#include <set>

#include "support/input_error.h"

namespace railjoint {

namespace {

// A relative profile path of the sweep file's (an axis, [set]) made absolute.
void anchor(SceneOverride& o, const std::filesystem::path& folder) {
  if (const auto* text = std::get_if<std::string>(&o.value); text && names_profile_file(o.section, o.key, *text)) {
    if (std::filesystem::path(*text).is_relative()) o.value = profile_path_in(folder, *text);
  }
}

// A row's message: each model's reason, "; "-separated.
void add_reason(std::string& message, const std::string& reason) {
  if (reason.empty()) return;
  if (!message.empty()) message += "; ";
  message += reason;
}

}  // namespace

CaseEvaluator::CaseEvaluator(const SweepFile& sweep, std::vector<CaseModel> models)
    : file_(sweep.file), sweep_folder_(folder_of(sweep.file)),
      base_(parse_scene_tree(sweep.base_text, sweep.base_scene)), fixed_(sweep.fixed),
      profile_files_(sweep.profiles ? sweep.profiles : std::make_shared<ProfileFiles>()), grid_(sweep),
      models_(std::move(models)) {
  for (const CaseModel& model : models_) model_cells_ += model.columns.size();
  // A path in the base scene is the base scene's, one in the sweep file the sweep file's.
  anchor_profile_paths(base_, folder_of(sweep.base_scene));
  for (SceneOverride& o : fixed_) anchor(o, sweep_folder_);

  // Every profile file now, once (the cases share the content). One the
  // base or [set] names that cannot be read would reject every case: the
  // sweep file's error. An axis's is its cases' (rows with the reason).
  // Read through the points here (tolerance 0): whether the file is a
  // profile at all does not depend on the smoothing a case asks for.
  const auto use = [&](const std::string& key, const std::string& path, const std::string& refuse_in) {
    const ProfileFile& file = profile_files_->get(path, profile_kind_of(key.substr(0, key.find('.'))), 0.0);
    if (!file.curve && !refuse_in.empty()) throw InputError(refuse_in, key, file.error);
    profile_uses_.push_back({key, path, file.sha256});
  };
  std::set<std::string> replaced;  // base keys no case reads: [set] or an axis gives them
  for (const SceneOverride& o : fixed_) replaced.insert(o.section + "." + o.key);
  for (const SweepAxis& axis : sweep.axes) replaced.insert(axis.name());
  for (const auto& [section, node] : base_) {
    if (!node.is_table()) continue;
    for (const auto& [key, value] : *node.as_table()) {
      const auto* text = value.as_string();
      const std::string name = std::string(section.str()) + "." + std::string(key.str());
      if (text && names_profile_file(section.str(), key.str(), text->get()) && !replaced.contains(name)) {
        use(name, text->get(), sweep.base_scene);
      }
    }
  }
  for (const SceneOverride& o : fixed_) {
    const auto* text = std::get_if<std::string>(&o.value);
    if (text && names_profile_file(o.section, o.key, *text)) use("set." + o.section + "." + o.key, *text, file_);
  }
  for (const SweepAxis& axis : sweep.axes) {
    if (!names_profile_file(axis.section, axis.key, "any.csv")) continue;  // a profile key at all
    for (SceneValue value : axis.values) {
      SceneOverride o{axis.section, axis.key, std::move(value)};
      anchor(o, sweep_folder_);
      if (const auto* text = std::get_if<std::string>(&o.value); text && names_profile_file(o.section, o.key, *text)) {
        use("axes." + axis.name(), *text, "");
      }
    }
  }

  // A key no scene has would reject every case: refuse the sweep file instead.
  // Each axis and [set] key alone on the base, with its (first) value, or
  // its range's start: only an unknown key or section is the sweep file's
  // fault; any other refusal may be one case's and becomes its row.
  const auto check_key = [&](SceneOverride o, const std::string& where) {
    anchor(o, sweep_folder_);
    try {
      read_scene_tree(base_, file_, {o}, SceneCheck::keys_only, profile_files_.get());
    } catch (const InputError& error) {
      const std::string text = error.what();
      const std::string name = o.section + "." + o.key;
      const bool unknown = (error.key() == name && text.find("unknown key") != std::string::npos) ||
                           (error.key() == o.section && text.find("unknown section") != std::string::npos);
      if (unknown) {
        throw InputError(file_, where + name, "is not a scene key (`railjoint simulate --help` lists them)");
      }
    }
  };
  for (const SweepAxis& axis : sweep.axes) {
    check_key({axis.section, axis.key, axis.values.empty() ? SceneValue(axis.from) : axis.values.front()}, "axes.");
  }
  for (const SceneOverride& o : fixed_) check_key(o, "set.");
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

Scene CaseEvaluator::read_case(std::uint64_t index, CaseScratch& scratch, CsvRow* row) const {
  grid_.overrides(index, scratch.overrides);
  if (row != nullptr) {
    row->integer(static_cast<long long>(index));
    for (const SceneOverride& o : scratch.overrides) row->value(o.value);
  }
  // The row shows the values as the sweep file gives them; the case reads
  // them with [set]'s, its profile paths from the sweep file's folder.
  for (SceneOverride& o : scratch.overrides) anchor(o, sweep_folder_);
  scratch.overrides.insert(scratch.overrides.end(), fixed_.begin(), fixed_.end());
  // The keys here; each model checks what its command checks: the kinematic
  // model's limits when a model first asks for the prediction (CaseInput,
  // load_scene's SceneCheck::model), the local model its own (`pressure`).
  Scene scene = read_scene_tree(base_, file_, scratch.overrides, SceneCheck::keys_only, profile_files_.get());
  // The rails every command derives when the scene gives no joint.length;
  // a simulating model adds its run's (CaseInput::crossing, scene_file.h).
  derive_minimum_rail_length(scene);
  return scene;
}

std::string CaseEvaluator::scene_refusal(std::uint64_t index) const {
  CaseScratch scratch;
  try {
    read_case(index, scratch, nullptr);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

CaseVerdict CaseEvaluator::append_row(std::uint64_t index, CaseScratch& scratch, CsvRow& row) const {
  const auto start = std::chrono::steady_clock::now();
  CaseVerdict verdict = CaseVerdict::ok;
  std::string message;
  CsvRow& cells = scratch.model_cells;
  cells.truncate(0, 0);
  // A refused scene still writes its case's values (before the throw).
  try {
    const Scene scene = read_case(index, scratch, &row);
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
  } catch (const std::exception& error) {
    // Not an input error: a fault of ours this case met. Its row says so and
    // the sweep goes on (one case must not stop 4,000, nor every rerun).
    verdict = CaseVerdict::failed;
    message = std::string("internal error (please report it with this case's values): ") + error.what();
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
