#pragma once
// One row of results.csv from one case: the base scene with the case's
// values (read as `--set` would read them, from the base's TOML tree parsed
// once), each model's cells, the verdict, why, and the wall time. The same
// case gives the same row on any thread, rank or run, but for the wall time.

#include <cstdint>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "scenes/report/csv_row.h"
#include "scenes/sweeps/case_grid.h"
#include "scenes/sweeps/case_model.h"
#include "scenes/scene_tree.h"
#include "scenes/sweeps/sweep_file.h"

namespace railjoint {

/// What a thread reuses from case to case (no allocation per case in the bookkeeping).
struct CaseScratch {
  std::vector<SceneOverride> overrides;
  CsvRow model_cells;
};

class CaseEvaluator {
 public:
  /// Throws InputError when the base scene is not valid TOML, or an axis names
  /// a key no scene has (a typo would otherwise reject every case).
  CaseEvaluator(const SweepFile& sweep, std::vector<CaseModel> models);

  const CaseGrid& grid() const { return grid_; }
  /// results.csv's first line (without the newline): case, the swept keys,
  /// verdict, message, the models' columns, wall_ms.
  std::string header() const;
  /// Appends case `index`'s row and its newline to `row`. Safe on many
  /// threads at once (each with its own scratch and row).
  CaseVerdict append_row(std::uint64_t index, CaseScratch& scratch, CsvRow& row) const;

 private:
  std::string file_;  ///< the sweep file, named in the messages of rejected cases
  toml::table base_;
  CaseGrid grid_;
  std::vector<CaseModel> models_;
  std::size_t model_cells_ = 0;
};

}  // namespace railjoint
