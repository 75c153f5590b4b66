#pragma once
// `railjoint sweep`: every case of a sweep file through its models, on
// `jobs` threads of this process (mpi_runner.h spreads them over MPI ranks),
// rows into the output folder (results_csv.h), progress on stderr.

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "scenes/sweeps/case_evaluator.h"
#include "scenes/sweeps/shard.h"
#include "scenes/sweeps/sweep_file.h"

namespace railjoint {

class ChunkDispenser;
class ProgressMeter;
class ResultsCsv;

struct SweepRunOptions {
  std::filesystem::path out_dir;
  int jobs = 1;       ///< threads of this process (MPI: of each rank)
  Shard shard;        ///< whole sweep by default
  bool progress = true;
  /// Called on the worker thread that has just handed in a chunk's rows,
  /// with the cases of this run done so far and in all (a caller's own
  /// progress display, the Python module's). An exception thrown here stops
  /// the sweep as a failing chunk does (case_pool.h): the rows handed in stay
  /// in results.csv, and a rerun with the same folder runs only the rest
  /// (the Python module's Ctrl-C).
  std::function<void(std::uint64_t done, std::uint64_t total)> after_chunk;
};

/// Cases counted by verdict (index: CaseVerdict).
using VerdictCounts = std::array<std::uint64_t, 5>;

/// Verdict counts added from many threads.
class VerdictTally {
 public:
  void add(const VerdictCounts& counts) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t v = 0; v < counts.size(); ++v) counts_[v] += counts[v];
  }
  VerdictCounts counts() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return counts_;
  }

 private:
  mutable std::mutex mutex_;
  VerdictCounts counts_{};
};

struct SweepSummary {
  std::string name;
  std::filesystem::path results;
  std::uint64_t cases = 0;            ///< in the sweep
  std::uint64_t in_shard = 0;         ///< of them this process's (--shard)
  std::uint64_t finished_before = 0;  ///< with a row from an earlier run
  std::uint64_t imported = 0;         ///< rows taken from shard files
  std::uint64_t ran = 0;              ///< run now
  VerdictCounts verdicts{};           ///< of the cases run now
  double wall_s = 0.0;
  int workers = 0;                    ///< threads (and ranks) that ran cases
};

/// Throws InputError when every case run now was rejected and the first
/// one's scene was refused before any model ran, with its reason: the rows
/// say why, but a sweep that computed nothing (a [set] value out of its
/// range refuses every case) must not exit 0.
void refuse_if_every_case_rejected(const CaseEvaluator& evaluator, std::optional<std::uint64_t> first_case,
                                   const SweepSummary& summary);

/// Cases run per chunk at most: enough that an analytic case (microseconds)
/// shares a lock and a write with thousands of others.
inline constexpr std::size_t kMaxChunkCases = 4096;

/// Runs cases[begin, end) of `todo` into `rows` (each row with its newline),
/// counting their verdicts (and each case on `progress` when given). The
/// unit of work of threads and MPI ranks alike.
void run_case_chunk(const CaseEvaluator& evaluator, const std::vector<std::uint64_t>& todo, std::size_t begin,
                    std::size_t end, std::string& rows, VerdictCounts& verdicts, ProgressMeter* progress = nullptr);

/// This process's `jobs` threads take chunks of results.todo() from the
/// dispenser until it is empty, and hand their rows to `results`.
/// `after_chunk` (may be empty): SweepRunOptions::after_chunk.
void run_local_chunks(const CaseEvaluator& evaluator, ResultsCsv& results, ChunkDispenser& dispenser, int jobs,
                      ProgressMeter& progress, VerdictTally& tally,
                      const std::function<void(std::uint64_t, std::uint64_t)>& after_chunk = {});

/// The summary's counts before any case runs (merging the rows of shard
/// files into a whole sweep's results.csv), and the cases left to run.
SweepSummary prepare_sweep(const SweepFile& sweep, const CaseEvaluator& evaluator, ResultsCsv& results,
                           const SweepRunOptions& options);

/// Runs the sweep on options.jobs threads. Throws InputError for a bad sweep
/// file, base scene or output folder.
SweepSummary run_sweep(const SweepFile& sweep, const SweepRunOptions& options);

/// The lines printed at the end: how many cases, by verdict, how fast, where.
std::string sweep_summary_text(const SweepSummary& summary);

}  // namespace railjoint
