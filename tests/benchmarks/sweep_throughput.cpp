// Sweep throughput: cases per second of `railjoint sweep` for the analytic
// and the simulate model, on 1 and 2 threads and on 2 MPI ranks, timed as
// whole processes (start-up included) and as the sweep itself reports its
// run (the "ran N in T s" line: reading the files, the cases, writing the
// rows; no process or MPI start-up). Prints one table, the scaling
// efficiency against one thread, and what a million cases cost in
// core-hours. Not a test: numbers of the machine it runs on (quote the
// load average printed with them).
//
//   build/tests/benchmarks/railjoint_sweep_throughput [--repeats N] [--analytic-cases N] [--simulate-cases N]

#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Timing {
  double process_wall_s = 0.0;  ///< whole process, from outside
  double process_cpu_s = 0.0;   ///< user + system of the process and its children (MPI ranks)
  double sweep_wall_s = 0.0;    ///< as the sweep reports its run
  long long cases = 0;
};

double cpu_of_children() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

// Runs one sweep in a fresh folder; exits on failure (a benchmark of a failing command means nothing).
Timing run_sweep(const std::string& launcher, const std::string& sweep, const fs::path& out, const std::string& jobs) {
  fs::remove_all(out);
  const std::string log = out.string() + ".log";
  const std::string command = launcher + RAILJOINT_EXE " sweep " + sweep + " --out " + out.string() + " --jobs " +
                              jobs + " > " + log + " 2>&1";
  const double cpu_before = cpu_of_children();
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  Timing t;
  t.process_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  t.process_cpu_s = cpu_of_children() - cpu_before;
  std::ifstream in(log);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (status != 0) {
    std::fprintf(stderr, "failed (%d): %s\n%s", status, command.c_str(), text.c_str());
    std::exit(1);
  }
  const auto ran = text.find("; ran ");
  if (ran == std::string::npos || std::sscanf(text.c_str() + ran, "; ran %lld in %lf s", &t.cases, &t.sweep_wall_s) != 2) {
    std::fprintf(stderr, "no summary line in:\n%s", text.c_str());
    std::exit(1);
  }
  return t;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Setup {
  std::string name;
  std::string launcher;
  std::string jobs;
  int workers;
};

}  // namespace

int main(int argc, char** argv) {
  int repeats = 3;
  long long analytic_cases = 400000;
  long long simulate_cases = 1000;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--repeats") repeats = std::max(1, std::atoi(argv[i + 1]));
    if (flag == "--analytic-cases") analytic_cases = std::max(100LL, std::atoll(argv[i + 1]));
    if (flag == "--simulate-cases") simulate_cases = std::max(10LL, std::atoll(argv[i + 1]));
  }
  // A folder of this run's own: two runs at once must not share files.
  std::string pattern = (fs::temp_directory_path() / "railjoint_sweep_throughput_XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) return 1;
  const fs::path dir = pattern;
  // The thesis's ranges, as the design map: theta x y_w (x beta for the analytic model).
  const long long a_side = std::max(10LL, static_cast<long long>(std::llround(std::sqrt(analytic_cases / 40.0))));
  const std::string analytic = (dir / "analytic.toml").string();
  std::ofstream(analytic) << "base = \"" RAILJOINT_SOURCE_DIR "/scenes/default.toml\"\nrun = [\"analytic\"]\n[axes]\n"
                          << "\"joint.beta\" = { from = 0.005, to = 0.05, count = 40 }\n"
                          << "\"joint.theta_deg\" = { from = 15.0, to = 90.0, count = " << a_side << " }\n"
                          << "\"wheel.y\" = { from = 0.0, to = 0.019, count = " << a_side << " }\n";
  const long long s_side = std::max(3LL, static_cast<long long>(std::llround(std::sqrt(static_cast<double>(simulate_cases)))));
  const std::string simulate = (dir / "simulate.toml").string();
  std::ofstream(simulate) << "base = \"" RAILJOINT_SOURCE_DIR "/scenes/default.toml\"\nrun = [\"simulate\"]\n[axes]\n"
                          << "\"joint.theta_deg\" = { from = 15.0, to = 90.0, count = " << s_side << " }\n"
                          << "\"wheel.y\" = { from = 0.0, to = 0.019, count = " << s_side << " }\n";

  std::vector<Setup> setups = {{"1 thread", "", "1", 1}, {"2 threads", "", "2", 2}};
  const bool mpi = RAILJOINT_HAVE_MPI && std::system("command -v mpirun > /dev/null 2>&1") == 0;
  // Open MPI refuses root without these; --oversubscribe lets 2 ranks share a machine that other jobs use too.
  if (mpi) {
    setups.push_back({"MPI 2 ranks", "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -np 2 ",
                      "1", 2});
  }
  std::printf("sweep throughput, median of %d runs; load average before: %s\n\n", repeats, load_average().c_str());
  std::printf("| model | setup | cases | sweep wall [s] | cases/s | per worker | vs 1 thread | efficiency | process wall [s] "
              "| CPU [s] | cases per CPU s | core-h per 10^6 cases |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const auto& [model, sweep] : {std::pair{std::string("analytic"), analytic}, std::pair{std::string("simulate"), simulate}}) {
    double single_rate = 0.0;
    for (const Setup& setup : setups) {
      std::vector<double> sweep_wall, process_wall, cpu;
      long long cases = 0;
      for (int r = 0; r < repeats; ++r) {
        const Timing t = run_sweep(setup.launcher, sweep, dir / (model + "_out"), setup.jobs);
        sweep_wall.push_back(t.sweep_wall_s);
        process_wall.push_back(t.process_wall_s);
        cpu.push_back(t.process_cpu_s);
        cases = t.cases;
      }
      const double rate = static_cast<double>(cases) / median(sweep_wall);
      if (setup.workers == 1) single_rate = rate;
      const double speedup = rate / single_rate;
      // Core-hours a million cases take at this setup's rate per worker.
      const double core_hours = 1e6 / (rate / setup.workers) / 3600.0;
      std::printf("| %s | %s | %lld | %.3f | %.0f | %.0f | %.2fx | %.0f %% | %.3f | %.3f | %.0f | %.3g |\n", model.c_str(),
                  setup.name.c_str(), cases, median(sweep_wall), rate, rate / setup.workers, speedup,
                  100.0 * speedup / setup.workers, median(process_wall), median(cpu),
                  static_cast<double>(cases) / median(cpu), core_hours);
      std::fflush(stdout);
    }
  }
  std::printf("\nload average after: %s\n", load_average().c_str());
  std::printf("efficiency: rate / (workers x the 1-thread rate). MPI: rank 0's main thread hands out the cases and\n"
              "writes the rows while a thread of its own and the other rank run them. Cases per CPU s: the cases over\n"
              "the user + system time of the whole process tree (start-up included), what the cases cost whatever\n"
              "else the machine runs. Core-hours per million cases: 10^6 / (rate per worker) / 3600, what a cluster\n"
              "pays at this efficiency.\n");
  fs::remove_all(dir);
  return 0;
}
