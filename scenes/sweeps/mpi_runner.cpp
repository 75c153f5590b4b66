// The MPI sweep (mpi_runner.h). Only the main thread of each rank calls MPI
// (MPI_THREAD_FUNNELED): rank 0's main thread hands out chunks and collects
// rows while its worker threads run cases like every other rank's.

#include "scenes/sweeps/mpi_runner.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

#include <mpi.h>

#include "scenes/sweeps/case_models.h"
#include "scenes/sweeps/results_csv.h"
#include "support/case_pool.h"
#include "support/input_error.h"
#include "support/progress_meter.h"

namespace railjoint {

namespace {

constexpr int kTagRows = 1;  ///< worker -> 0: verdict counts + the rows of its last chunk; asks for the next
constexpr int kTagWork = 2;  ///< 0 -> worker: the case indices of a chunk
constexpr int kTagStop = 3;  ///< 0 -> worker: nothing left
// How long rank 0's main thread sleeps when no rank is waiting: short next
// to a chunk, long enough to leave its core to the worker threads.
constexpr auto kIdlePoll = std::chrono::milliseconds(1);

// MPI_Init_thread and MPI_Finalize around the sweep, also when it throws.
class MpiSession {
 public:
  MpiSession() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiSession() { MPI_Finalize(); }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0;
  int size_ = 1;
};

void broadcast(std::string& text) {
  unsigned long long size = text.size();
  MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  text.resize(size);
  MPI_Bcast(text.data(), static_cast<int>(size), MPI_CHAR, 0, MPI_COMM_WORLD);
}

// A chunk's message from a worker: the verdict counts, then the rows.
std::string rows_message(const VerdictCounts& verdicts, const std::string& rows) {
  std::string message(sizeof verdicts, '\0');
  std::memcpy(message.data(), verdicts.data(), sizeof verdicts);
  return message + rows;
}

// Runs a chunk on `jobs` threads; rows in the chunk's order.
void run_chunk_threads(const CaseEvaluator& evaluator, const std::vector<std::uint64_t>& cases, int jobs,
                       std::string& rows, VerdictCounts& verdicts) {
  if (jobs <= 1 || cases.size() < 2) {
    run_case_chunk(evaluator, cases, 0, cases.size(), rows, verdicts);
    return;
  }
  std::mutex mutex;
  std::map<std::size_t, std::string> pieces;
  ChunkDispenser dispenser(cases.size(), static_cast<std::size_t>(jobs), kMaxChunkCases);
  run_chunks(dispenser, jobs, [&](Chunk chunk) {
    std::string piece;
    VerdictCounts counts{};
    run_case_chunk(evaluator, cases, chunk.begin, chunk.end, piece, counts);
    std::lock_guard<std::mutex> lock(mutex);
    pieces.emplace(chunk.begin, std::move(piece));
    for (std::size_t v = 0; v < counts.size(); ++v) verdicts[v] += counts[v];
  });
  for (auto& [begin, piece] : pieces) rows += piece;
}

void work(const CaseEvaluator& evaluator, int jobs) {
  std::string rows;
  VerdictCounts verdicts{};
  for (;;) {
    const std::string message = rows_message(verdicts, rows);
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, kTagRows, MPI_COMM_WORLD);
    MPI_Status status;
    MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    int count = 0;
    MPI_Get_count(&status, MPI_UNSIGNED_LONG_LONG, &count);
    std::vector<std::uint64_t> cases(static_cast<std::size_t>(count));
    MPI_Recv(cases.data(), count, MPI_UNSIGNED_LONG_LONG, 0, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (status.MPI_TAG == kTagStop) return;
    rows.clear();
    verdicts = {};
    run_chunk_threads(evaluator, cases, jobs, rows, verdicts);
  }
}

// Rank 0: serves the other ranks from its main thread while its worker
// threads take chunks from the same dispenser.
void coordinate(const CaseEvaluator& evaluator, ResultsCsv& results, int ranks, const SweepRunOptions& options, const std::string& label, SweepSummary& summary) {
  const std::vector<std::uint64_t>& todo = results.todo();
  const int workers = (ranks - 1) * options.jobs + options.jobs;
  ChunkDispenser dispenser(todo.size(), static_cast<std::size_t>(workers), kMaxChunkCases);
  ProgressMeter progress(label, todo.size(), options.progress && !todo.empty());
  VerdictTally tally;
  std::exception_ptr local_error;
  std::thread local([&] {
    try {
      run_local_chunks(evaluator, results, dispenser, options.jobs, progress, tally);
    } catch (...) {
      local_error = std::current_exception();
    }
  });

  struct Sent {
    Chunk chunk;
    std::chrono::steady_clock::time_point at;
  };
  std::map<int, Sent> outstanding;
  int active = ranks - 1;
  try {
    while (active > 0) {
      int arrived = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, kTagRows, MPI_COMM_WORLD, &arrived, &status);
      if (!arrived) {
        std::this_thread::sleep_for(kIdlePoll);
        continue;
      }
      int bytes = 0;
      MPI_Get_count(&status, MPI_CHAR, &bytes);
      std::string message(static_cast<std::size_t>(bytes), '\0');
      const int source = status.MPI_SOURCE;
      MPI_Recv(message.data(), bytes, MPI_CHAR, source, kTagRows, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (const auto done = outstanding.find(source); done != outstanding.end()) {
        VerdictCounts verdicts{};
        std::memcpy(verdicts.data(), message.data(), sizeof verdicts);
        const Chunk chunk = done->second.chunk;
        results.submit(chunk.begin, chunk.end, message.substr(sizeof verdicts));
        progress.add(chunk.end - chunk.begin);
        tally.add(verdicts);
        dispenser.finished(chunk, std::chrono::duration<double>(std::chrono::steady_clock::now() - done->second.at).count());
        outstanding.erase(done);
      }
      const Chunk next = dispenser.next();
      if (next.empty()) {
        MPI_Send(nullptr, 0, MPI_UNSIGNED_LONG_LONG, source, kTagStop, MPI_COMM_WORLD);
        --active;
        continue;
      }
      const std::vector<std::uint64_t> cases(todo.begin() + static_cast<std::ptrdiff_t>(next.begin),
                                             todo.begin() + static_cast<std::ptrdiff_t>(next.end));
      MPI_Send(cases.data(), static_cast<int>(cases.size()), MPI_UNSIGNED_LONG_LONG, source, kTagWork, MPI_COMM_WORLD);
      outstanding[source] = {next, std::chrono::steady_clock::now()};
    }
  } catch (const std::exception& error) {
    // Rows cannot be written (a full disk): nothing to do but stop every rank.
    std::fprintf(stderr, "railjoint: error: %s\n", error.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  local.join();
  if (local_error) std::rethrow_exception(local_error);
  summary.verdicts = tally.counts();
  summary.workers = workers;
}

}  // namespace

bool mpi_built() { return true; }

MpiSweepResult run_sweep_mpi(const std::string& sweep_path, const SweepRunOptions& options) {
  MpiSession mpi;
  const auto start = std::chrono::steady_clock::now();  // the sweep's time, not MPI's start-up
  MpiSweepResult result;
  result.is_writer = mpi.rank() == 0;
  const std::vector<std::string> known = case_model_names();

  // Rank 0 checks everything a threaded run checks before any case runs;
  // the others learn whether to go on.
  std::optional<SweepFile> sweep;
  std::optional<CaseEvaluator> evaluator;
  std::optional<ResultsCsv> results;
  std::exception_ptr failure;
  int ready = 1;
  if (mpi.rank() == 0) {
    try {
      sweep = load_sweep_file(sweep_path, known);
      evaluator.emplace(*sweep, case_models(sweep->models));
      results.emplace(options.out_dir, *sweep, *evaluator, options.shard);
    } catch (...) {
      failure = std::current_exception();
      ready = 0;
    }
  }
  MPI_Bcast(&ready, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (!ready) {
    if (failure) std::rethrow_exception(failure);
    return result;
  }
  std::string sweep_text = sweep ? sweep->text : std::string();
  std::string base_text = sweep ? sweep->base_text : std::string();
  broadcast(sweep_text);
  broadcast(base_text);
  if (mpi.rank() != 0) {
    const SweepFile copy = parse_sweep_file(sweep_text, sweep_path, base_text, known);
    const CaseEvaluator worker_evaluator(copy, case_models(copy.models));
    work(worker_evaluator, options.jobs);
    return result;
  }

  SweepSummary& summary = result.summary;
  summary = prepare_sweep(*sweep, *evaluator, *results, options);
  const std::optional<std::uint64_t> first_case =
      results->todo().empty() ? std::nullopt : std::optional(results->todo().front());
  coordinate(*evaluator, *results, mpi.size(), options, sweep->name + " (" + std::to_string(mpi.size()) + " ranks)",
             summary);
  results->finish();
  summary.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  refuse_if_every_case_rejected(*evaluator, first_case, summary);
  return result;
}

}  // namespace railjoint
