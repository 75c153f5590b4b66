#pragma once
// One row of results.csv from one case: the base scene with [set]'s and the
// case's values (read as `--set` would read them, from the base's TOML tree
// parsed once, its profile files read once), each model's cells, the
// verdict, why, and the wall time. The same case gives the same row on any
// thread, rank or run, but for the wall time.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "scenes/report/csv_row.h"
#include "scenes/sweeps/case_grid.h"
#include "scenes/sweeps/case_model.h"
#include "scenes/profile_files.h"
#include "scenes/scene_tree.h"
#include "scenes/sweeps/sweep_file.h"

namespace railjoint {

/// What a thread reuses from case to case (no allocation per case in the bookkeeping).
struct CaseScratch {
  std::vector<SceneOverride> overrides;
  CsvRow model_cells;
};

/// A profile file a sweep reads, by the key that names it ("wheel.profile"
/// in the base scene, "set.wheel.profile", "axes.wheel.profile").
struct SweepProfile {
  std::string key;
  std::string path;    ///< absolute
  std::string sha256;  ///< of the content every case uses; empty: it could not be read
};

class CaseEvaluator {
 public:
  /// Throws InputError when the base scene is not valid TOML, an axis or a
  /// [set] key names a key no scene has (a typo would otherwise reject every
  /// case), or a profile file of the base scene or of [set] cannot be read.
  /// Reads every profile file the sweep names, once: the cases use that
  /// content whatever happens to the files while they run.
  CaseEvaluator(const SweepFile& sweep, std::vector<CaseModel> models);

  /// The profile files the sweep's cases read, for its fingerprint.
  const std::vector<SweepProfile>& profiles() const { return profile_uses_; }

  const CaseGrid& grid() const { return grid_; }
  /// results.csv's first line (without the newline): case, the swept keys,
  /// verdict, message, the models' columns, wall_ms.
  std::string header() const;
  /// Appends case `index`'s row and its newline to `row`. Safe on many
  /// threads at once (each with its own scratch and row).
  CaseVerdict append_row(std::uint64_t index, CaseScratch& scratch, CsvRow& row) const;
  /// Why case `index`'s scene is refused before any model runs (a value
  /// out of its range), or "" when it reads.
  std::string scene_refusal(std::uint64_t index) const;

 private:
  /// Case `index`'s scene: its overrides (the sweep file's values, then
  /// [set]'s) read onto the base scene. Throws InputError as the reader does.
  Scene read_case(std::uint64_t index, CaseScratch& scratch, CsvRow* row) const;

  std::string file_;  ///< the sweep file, named in the messages of rejected cases
  std::filesystem::path sweep_folder_;  ///< a relative profile path of an axis is read from here
  toml::table base_;  ///< its profile paths absolute
  std::vector<SceneOverride> fixed_;  ///< [set], its profile paths absolute
  std::shared_ptr<ProfileFiles> profile_files_;
  std::vector<SweepProfile> profile_uses_;
  CaseGrid grid_;
  std::vector<CaseModel> models_;
  std::size_t model_cells_ = 0;
};

}  // namespace railjoint
