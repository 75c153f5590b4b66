#include "scenes/sweeps/sweep_runner.h"

#include <chrono>
#include <string>

#include "scenes/report/report_text.h"
#include "support/input_error.h"

#include "scenes/sweeps/case_models.h"
#include "scenes/sweeps/results_csv.h"
#include "support/case_pool.h"
#include "support/progress_meter.h"

namespace railjoint {

void run_case_chunk(const CaseEvaluator& evaluator, const std::vector<std::uint64_t>& todo, std::size_t begin,
                    std::size_t end, std::string& rows, VerdictCounts& verdicts, ProgressMeter* progress) {
  CaseScratch scratch;
  CsvRow row;
  row.str() = std::move(rows);
  // The shared counter is touched every 64 cases, not every case.
  std::uint64_t pending = 0;
  for (std::size_t i = begin; i < end; ++i) {
    ++verdicts[static_cast<std::size_t>(evaluator.append_row(todo[i], scratch, row))];
    if (progress != nullptr && ++pending == 64) {
      progress->add(pending);
      pending = 0;
    }
  }
  if (progress != nullptr) progress->add(pending);
  rows = std::move(row.str());
}

void run_local_chunks(const CaseEvaluator& evaluator, ResultsCsv& results, ChunkDispenser& dispenser, int jobs,
                      ProgressMeter& progress, VerdictTally& tally,
                      const std::function<void(std::uint64_t, std::uint64_t)>& after_chunk) {
  run_chunks(dispenser, jobs, [&](Chunk chunk) {
    std::string rows;
    VerdictCounts verdicts{};
    run_case_chunk(evaluator, results.todo(), chunk.begin, chunk.end, rows, verdicts, &progress);
    results.submit(chunk.begin, chunk.end, std::move(rows));
    tally.add(verdicts);
    if (after_chunk) after_chunk(progress.done(), results.todo().size());
  });
}

SweepSummary prepare_sweep(const SweepFile& sweep, const CaseEvaluator& evaluator, ResultsCsv& results,
                           const SweepRunOptions& options) {
  SweepSummary summary;
  summary.name = sweep.name;
  summary.results = results.path();
  summary.cases = evaluator.grid().size();
  summary.finished_before = results.finished_count();
  if (options.shard.whole()) summary.imported = results.import_shard_rows();
  const Shard& shard = options.shard;
  summary.in_shard = (summary.cases + shard.count - shard.index) / shard.count;  // cases i-1, i-1+N, ... below the count
  summary.ran = results.plan().size();
  return summary;
}

SweepSummary run_sweep(const SweepFile& sweep, const SweepRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const CaseEvaluator evaluator(sweep, case_models(sweep.models));
  ResultsCsv results(options.out_dir, sweep, evaluator, options.shard);
  SweepSummary summary = prepare_sweep(sweep, evaluator, results, options);
  const std::vector<std::uint64_t>& todo = results.todo();
  summary.workers = options.jobs;

  VerdictTally tally;
  {
    ProgressMeter progress(sweep.name, todo.size(), options.progress && !todo.empty());
    ChunkDispenser dispenser(todo.size(), static_cast<std::size_t>(options.jobs), kMaxChunkCases);
    run_local_chunks(evaluator, results, dispenser, options.jobs, progress, tally, options.after_chunk);
  }
  summary.verdicts = tally.counts();
  const std::optional<std::uint64_t> first_case = todo.empty() ? std::nullopt : std::optional(todo.front());
  results.finish();
  summary.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  refuse_if_every_case_rejected(evaluator, first_case, summary);
  return summary;
}

void refuse_if_every_case_rejected(const CaseEvaluator& evaluator, std::optional<std::uint64_t> first_case,
                                   const SweepSummary& summary) {
  if (!first_case || summary.ran == 0 ||
      summary.verdicts[static_cast<std::size_t>(CaseVerdict::rejected)] != summary.ran) {
    return;
  }
  // The first case's scene again (a refusal costs microseconds), for its
  // reason. A scene that reads but whose models refuse it (`pressure` on a
  // joint without a gap) still gave the other models' columns.
  const std::string reason = evaluator.scene_refusal(*first_case);
  if (reason.empty()) return;
  throw InputError(summary.results.string(), "",
                   "every case run (" + std::to_string(summary.ran) + ") was rejected, the first one's scene "
                   "before any model ran, so the sweep computed nothing: " + reason);
}

std::string sweep_summary_text(const SweepSummary& s) {
  const auto n = [](std::uint64_t count) { return std::to_string(count); };
  std::string text = "sweep " + s.name + ": " + n(s.cases) + " cases";
  if (s.in_shard != s.cases) text += ", " + n(s.in_shard) + " in this shard";
  text += "; " + n(s.finished_before) + " had a row already";
  if (s.imported > 0) text += ", " + n(s.imported) + " taken from shard files";
  text += "; ran " + n(s.ran) + format_number(" in %.3f s", s.wall_s) + " on " + std::to_string(s.workers) + " worker" +
          (s.workers == 1 ? "" : "s");
  if (s.ran > 0 && s.wall_s > 0) text += format_number(" (%.4g cases/s)", static_cast<double>(s.ran) / s.wall_s);
  text += "\n";
  if (s.ran > 0) {
    text += "verdicts:";
    for (std::size_t v = 0; v < s.verdicts.size(); ++v) {
      text += std::string(" ") + to_string(static_cast<CaseVerdict>(v)) + " " + n(s.verdicts[v]);
    }
    text += "\n";
  }
  return text + "results: " + s.results.string() + "\n";
}

}  // namespace railjoint
