// railjoint: checks the kinematic model of a wheel crossing an inclined dipped
// insulated rail joint against a rigid-body simulation.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "geometry/mesh_export.h"
#include "scenes/cli/commands.h"
#include "scenes/closest_names.h"
#include "scenes/sweeps/mpi_runner.h"
#include "support/atomic_file.h"
#include "support/input_error.h"
#include "support/interrupted_run.h"

namespace {

// "study convergence" for an error in `railjoint study convergence ...`: the
// deepest sub-command the parser reached, whose --help lists what it takes.
std::string command_path(const CLI::App& app) {
  std::string path;
  const CLI::App* at = &app;
  while (!at->get_subcommands().empty()) {
    at = at->get_subcommands().front();
    path += (path.empty() ? "" : " ") + at->get_name();
  }
  return path;
}

int print_error(const std::string& text, int exit_code) {
  std::fflush(stdout);
  std::cerr << "railjoint: error: " << railjoint::one_line(text) << "\n";
  return exit_code;
}

// CLI11 calls a mistyped command (`railjoint analytc`) a missing one ("A
// subcommand is required"); the user needs the name they meant.
void check_command_name(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return;
  std::vector<std::string> names;
  for (const CLI::App* command : app.get_subcommands({})) names.push_back(command->get_name());
  const std::string typed = argv[1];
  if (std::find(names.begin(), names.end(), typed) != names.end()) return;
  std::string known;
  for (const std::string& name : names) known += (known.empty() ? "" : ", ") + name;
  throw CLI::ValidationError("unknown command '" + typed + "'" + railjoint::did_you_mean(typed, names) +
                             "; the commands are " + known);
}

}  // namespace

// The same command line run by the executable `name` beside this one, in
// this process (execv), so a launcher's environment is its own; returns only
// when there is none or it cannot start.
void run_sibling(const char* name, char** argv) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return;
  const std::filesystem::path sibling = self.parent_path() / name;
  if (!std::filesystem::is_regular_file(sibling, error)) return;
  execv(sibling.c_str(), argv);
}

// Under an MPI launcher a sweep runs in railjoint-mpi, which links Open MPI
// (this one does not: it would load it in every run).
void hand_mpi_sweep_to_railjoint_mpi(int argc, char** argv) {
  if (railjoint::mpi_built() || !railjoint::started_by_mpi_launcher()) return;
  if (argc < 2 || std::string(argv[1]) != "sweep") return;
  run_sibling("railjoint-mpi", argv);  // returns only on failure: then this one refuses the sweep
}

// A command that writes a mesh file (`mesh`; `render` and `simulate
// --render-out`, the glTF) runs in railjoint-assimp, which links assimp:
// this one does not, for its start-up cost (docs/rendering.md, "GL back ends").
void hand_mesh_writing_to_railjoint_assimp(int argc, char** argv) {
  if (railjoint::mesh_export_built() || argc < 2) return;
  const std::string command = argv[1];
  bool writes_meshes = command == "mesh" || command == "render";
  for (int i = 2; i < argc && command == "simulate"; ++i) {
    writes_meshes = writes_meshes || std::string(argv[i]).starts_with("--render-out");
  }
  if (writes_meshes) run_sibling("railjoint-assimp", argv);
}

int main(int argc, char** argv) {
  hand_mpi_sweep_to_railjoint_mpi(argc, argv);
  hand_mesh_writing_to_railjoint_assimp(argc, argv);
  // A file-size limit (ulimit -f) makes a write fail with EFBIG, reported
  // with the file's name like a full disk, instead of killing the run
  // silently with SIGXFSZ and leaving its temporary behind.
  std::signal(SIGXFSZ, SIG_IGN);
  // Ctrl-C, kill, a batch system's SIGTERM: no hidden temporary is left.
  railjoint::remove_on_interrupt();
  // A report into a file or a pipe leaves in one write when the run ends, so
  // a failed write is reported there with its reason (a full disk).
  static char stdout_buffer[1 << 16];
  if (!isatty(fileno(stdout))) std::setvbuf(stdout, stdout_buffer, _IOFBF, sizeof stdout_buffer);
  CLI::App app{
      "railjoint: vertical impact of a train wheel crossing an inclined (non-orthogonal) dipped\n"
      "insulated rail joint. Analytic kinematic model (thesis ch. 3-4) checked against a Bullet\n"
      "rigid-body simulation; the local contact-pressure model of a patch crossing the end-post\n"
      "gap (ch. 5-6). Units are SI (m, kg, s, rad) unless a key or flag says _deg.",
      "railjoint"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("railjoint ") + RAILJOINT_VERSION);
  railjoint::cli::add_analytic_command(app);
  railjoint::cli::add_simulate_command(app);
  railjoint::cli::add_mesh_command(app);
  railjoint::cli::add_validate_command(app);
  railjoint::cli::add_study_command(app);
  railjoint::cli::add_render_command(app);
  railjoint::cli::add_pressure_command(app);
  railjoint::cli::add_sweep_command(app);

  try {
    check_command_name(app, argc, argv);
    app.parse(argc, argv);
    // A report that did not reach its reader (stdout on a full disk, a
    // closed pipe) is a failed run, not a silent success.
    railjoint::finish_standard_output();
  } catch (const CLI::Success& help) {
    const int exit_code = app.exit(help);  // --help: the text on stdout, exit 0
    try {
      railjoint::finish_standard_output();  // ... unless it was lost
    } catch (const std::exception& error) {
      return print_error(error.what(), 1);
    }
    return exit_code;
  } catch (const CLI::ParseError& error) {
    // A bad flag is bad input like a bad scene key: exit 2, one line.
    const std::string command = command_path(app);
    const std::string help = "`railjoint " + command + (command.empty() ? "" : " ") + "--help`";
    return print_error((command.empty() ? "" : command + ": ") + error.what() + " (" + help + " lists the options)", 2);
  } catch (const railjoint::InputError& error) {
    return print_error(error.what(), 2);
  } catch (const std::exception& error) {
    return print_error(error.what(), 1);
  }
  return 0;
}
