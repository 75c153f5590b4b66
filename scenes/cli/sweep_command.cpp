// `railjoint sweep SWEEP.toml --out DIR`: every case of a sweep file through
// its models on every core (or MPI ranks, or one shard of N), one row per
// case in DIR/results.csv, resumable (scenes/sweeps/).

#include <cstdio>
#include <string>

#include "scenes/cli/command.h"
#include "scenes/cli/commands.h"
#include "scenes/sweeps/case_models.h"
#include "scenes/sweeps/mpi_runner.h"
#include "scenes/sweeps/sweep_runner.h"
#include "support/case_pool.h"

namespace railjoint::cli {

namespace {

struct SweepOptions {
  std::string sweep_path;
  std::string out_dir;
  int jobs = 0;  ///< 0: every core (threads), 1 per rank (MPI)
  std::string shard;
};

constexpr const char* kDescription =
    "Runs a grid of scenes: a base scene and axes over any scene key (a list, an even or log range, or\n"
    "random / Latin-hypercube samples), every case through the models of `run` (analytic, simulate,\n"
    "pressure, forces), one row per case in OUT/results.csv: its values, the analytic forms, the\n"
    "simulated jump and its errors (or P1 and P2), the verdict (ok, suspect, no_impact, failed, rejected:\n"
    "a case the scene reader or a model refuses is a row with the reason) and the wall time. Rows are\n"
    "written in case order as cases finish; a rerun with the same --out runs only the cases without a\n"
    "row. Under mpirun the ranks share the cases (rank 0 writes); --shard i/N runs every N-th case for\n"
    "job arrays.";

void run_sweep_command(const SweepOptions& options) {
  SweepRunOptions run;
  run.out_dir = options.out_dir;
  if (!options.shard.empty()) run.shard = parse_shard(options.shard);
  if (started_by_mpi_launcher()) {
    // One rank per core is the usual layout: one thread per rank unless --jobs says otherwise.
    run.jobs = options.jobs > 0 ? options.jobs : 1;
    const MpiSweepResult result = run_sweep_mpi(options.sweep_path, run);
    if (result.is_writer) std::fputs(sweep_summary_text(result.summary).c_str(), stdout);
    return;
  }
  run.jobs = options.jobs > 0 ? options.jobs : available_cores();
  const SweepFile sweep = load_sweep_file(options.sweep_path, case_model_names());
  std::fputs(sweep_summary_text(run_sweep(sweep, run)).c_str(), stdout);
}

void add_sweep_options(CLI::App& cmd, SweepOptions& options) {
  cmd.add_option("sweep", options.sweep_path,
                 "Sweep file (TOML):\n"
                 "  base = \"scene.toml\"            base scene, relative to the sweep file\n"
                 "  run = [\"analytic\", \"simulate\"]  models run on every case (also \"pressure\", and \"forces\":\n"
                 "                                  P1, P2 and Jenkins's of a scene with contact.law = \"hertz\")\n"
                 "  [axes]  \"section.key\" = [v1, v2, ...]                 a list\n"
                 "          \"section.key\" = { from = a, to = b, count = n }  an even range\n"
                 "          add scale = \"log\" for a log range; leave out count to sample it\n"
                 "  [sample] count = N, seed = S, method = \"latin_hypercube\" | \"random\"\n"
                 "  [set]   \"section.key\" = value   fixed for every case (not also an axis)\n"
                 "  a profile file is relative to the file naming it: the base scene's, or this one's")
      ->required();
  cmd.add_option("--out", options.out_dir,
                 "Output folder: results.csv (results.shard-i-of-N.csv with --shard) and sweep.json, the\n"
                 "fingerprints of the sweep file, base scene and profile files; a changed sweep is refused.\n"
                 "One run writes a folder (or a shard's file) at a time: a second is refused while the first lives")
      ->required();
  cmd.add_option("--jobs", options.jobs,
                 "Threads running cases (default: every core this process may use; under MPI: 1 per rank)")
      ->check(CLI::Range(1, 4096));
  cmd.add_option("--shard", options.shard,
                 "Run only shard i of N (cases i-1, i-1+N, ...), e.g. --shard $SLURM_ARRAY_TASK_ID/8 with\n"
                 "--array=1-8; the same --out for all shards, then a plain run merges their rows");
}

}  // namespace

void add_sweep_command(CLI::App& app) { add_command(app, "sweep", kDescription, add_sweep_options, run_sweep_command); }

}  // namespace railjoint::cli
