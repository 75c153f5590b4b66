#pragma once
// The one scheduler: many independent cases on every core. Worker threads
// take chunks of consecutive items from a shared dispenser, largest first (a
// share of what is left per worker, "guided"), so a cheap case (microseconds)
// costs no lock of its own, and the last, expensive ones (milliseconds to
// seconds) still spread evenly over the workers. Nothing mutable is shared but
// the dispenser and what the caller locks itself. The sweeps and every study
// run on it (support/DESIGN.md, "One scheduler, one progress meter").

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "support/progress_meter.h"

namespace railjoint {

/// The processors this process may run on (its CPU affinity: taskset, cgroups, Slurm).
int available_cores();

struct Chunk {
  std::size_t begin = 0;
  std::size_t end = 0;  ///< one past the last item; begin == end: nothing left
  bool empty() const { return begin == end; }
};

/// Hands out [0, count) in chunks; safe to call from many threads. A chunk
/// is also kept to about kChunkSeconds of work, from the time the finished
/// chunks took: rows reach the disk (and a kill loses) no more than that per
/// worker, whether a case takes microseconds or a second. Until the first
/// chunk is timed, chunks hold one item.
class ChunkDispenser {
 public:
  static constexpr double kChunkSeconds = 0.2;

  /// `workers`: how many take chunks (sets the share); `max_chunk` caps a chunk.
  ChunkDispenser(std::size_t count, std::size_t workers, std::size_t max_chunk);
  Chunk next();
  /// A chunk handed out earlier took `seconds` to run.
  void finished(Chunk chunk, double seconds);

 private:
  std::mutex mutex_;
  std::size_t next_ = 0;
  std::size_t count_;
  std::size_t workers_;
  std::size_t max_chunk_;
  double timed_items_ = 0.0;
  double timed_seconds_ = 0.0;
};

/// Runs work(chunk) on `jobs` threads (the calling thread is one of them)
/// until the dispenser is empty. The first exception a chunk throws stops
/// the hand-out and is rethrown here once every thread has ended.
void run_chunks(ChunkDispenser& dispenser, int jobs, const std::function<void(Chunk)>& work);

/// How a study runs its cases: on how many threads, and the label of its
/// progress on stderr (empty: none).
struct ParallelRuns {
  int jobs = 1;
  std::string progress_label;
};

/// results[i] = evaluate(i) for i in [0, count), on runs.jobs threads, one
/// item per chunk (a study's every item is a simulation or more).
template <typename Result, typename Evaluate>
std::vector<Result> parallel_map(std::size_t count, const ParallelRuns& runs, Evaluate evaluate) {
  std::vector<Result> results(count);
  const int jobs = std::max(runs.jobs, 1);
  ChunkDispenser dispenser(count, static_cast<std::size_t>(jobs), 1);
  ProgressMeter progress(runs.progress_label, count, !runs.progress_label.empty());
  run_chunks(dispenser, jobs, [&](Chunk chunk) {
    for (std::size_t i = chunk.begin; i < chunk.end; ++i) {
      results[i] = evaluate(i);
      progress.add(1);
    }
  });
  return results;
}

}  // namespace railjoint
