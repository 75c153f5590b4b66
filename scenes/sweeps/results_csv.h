#pragma once
// The output folder of a sweep: results.csv (results.shard-i-of-N.csv for
// --shard i/N), one row per case in case order, and sweep.json, the
// fingerprints of the sweep file, its base scene and the profile files
// (SHA-256 of each) the rows belong to.
//
// Rows reach the disk, flushed, as soon as every earlier case's row has (a
// reorder buffer): a killed sweep loses only the cases in flight and the few
// finished ones waiting for them. A rerun with the same folder skips the
// cases with a row; a sweep file, base scene or profile file changed since is
// refused. A last row cut short by a kill is dropped and its case run again;
// any other line that is not this sweep's row of its case is refused. One
// writer per results file at a time (sweep_folder_lock.h); only regular
// files are read.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "scenes/sweeps/case_evaluator.h"
#include "scenes/sweeps/shard.h"
#include "scenes/sweeps/sweep_folder_lock.h"
#include "scenes/sweeps/sweep_file.h"

namespace railjoint {

class ResultsCsv {
 public:
  /// Locks the results file against other writers, creates `dir` and
  /// sweep.json, or checks that sweep.json is this sweep's (throws
  /// InputError naming the folder, --out and what changed); reads the rows
  /// already there, each checked against `evaluator`'s case.
  ResultsCsv(const std::filesystem::path& dir, const SweepFile& sweep, const CaseEvaluator& evaluator,
             const Shard& shard);
  ~ResultsCsv();
  ResultsCsv(const ResultsCsv&) = delete;
  ResultsCsv& operator=(const ResultsCsv&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// Cases with a row in the file (from earlier runs, and imported).
  std::uint64_t finished_count() const { return finished_count_; }

  /// Whole sweep only: copies into results.csv the rows of shard files in the
  /// folder (results.shard-*.csv) for cases it lacks, so a plain run after
  /// the shards merges them, running nothing twice. Returns how many.
  std::uint64_t import_shard_rows();

  /// Fixes the cases to run (after any import): this shard's cases without a
  /// row, in case order, the order in which submit() writes them.
  const std::vector<std::uint64_t>& plan();
  /// The cases plan() fixed.
  const std::vector<std::uint64_t>& todo() const { return todo_; }

  /// Rows of todo()[begin, end), in that order, each ending in '\n'.
  /// Thread-safe; written and flushed once every earlier chunk is.
  void submit(std::size_t begin, std::size_t end, std::string rows);

  /// After the last chunk: the rows in case order on disk (rewritten once if
  /// an import or an interrupted run left them out of order, holding a byte
  /// offset per case rather than the rows).
  void finish();

 private:
  void read_existing();
  void write(const std::string& rows, std::uint64_t first_case);
  /// Throws InputError unless `line` is a row of a case of this sweep with
  /// no row yet; returns its case.
  std::uint64_t checked_case(const std::string& line, const std::filesystem::path& file, std::uint64_t line_number);

  const CaseEvaluator& evaluator_;
  std::string header_;
  std::size_t fields_ = 0;  ///< a row's fields: the column line's
  std::unique_ptr<SweepFolderLock> lock_;
  CsvRow prefix_;  ///< checked_case's scratch: a case's number and values
  std::vector<SceneOverride> prefix_overrides_;
  std::filesystem::path path_;
  std::uint64_t cases_;
  Shard shard_;
  std::vector<std::uint8_t> finished_;  ///< a byte per case of the sweep
  std::uint64_t finished_count_ = 0;
  std::vector<std::uint64_t> todo_;
  std::FILE* file_ = nullptr;
  bool in_order_ = true;          ///< the file's rows are in ascending case order
  std::uint64_t last_case_ = 0;   ///< the last row's case
  bool any_row_ = false;

  std::mutex mutex_;
  std::size_t next_ = 0;  ///< todo position of the next row to write
  std::map<std::size_t, std::pair<std::size_t, std::string>> waiting_;  ///< begin -> (end, rows)
};

}  // namespace railjoint
