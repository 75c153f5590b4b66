#pragma once
// What every command that reads one scene shares, declared once: the scene
// file argument, the --set overrides, loading and checking the scene, and the
// file in its errors. The checks of the model, the simulation and the
// renderer know keys, not files: an InputError the run raises without a file
// is raised again naming the scene file.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "scenes/scene.h"
#include "scenes/scene_file.h"

namespace railjoint::cli {

struct SceneCommandHelp {
  std::string name;         ///< the sub-command, e.g. "simulate"
  std::string description;  ///< what it does, for --help
  std::string scene;        ///< help of the scene argument: the keys it reads
  std::string set_example;  ///< e.g. "wheel.y=0.01", shown in the help of --set
  /// The scene sections the command reads; a --set into any other section
  /// changes nothing and is refused by name (empty: every section is read).
  /// A scene file may hold the others: it is shared between commands.
  std::vector<std::string> sections_read = {};
};

/// Adds the sub-command to `parent` with the scene argument and --set; when
/// called it loads the scene (with `check`) and calls `run`.
CLI::App* add_scene_command(CLI::App& parent, const SceneCommandHelp& help, SceneCheck check,
                            std::function<void(const Scene&)> run);

/// The same for a command with options of its own (added by add_options
/// after the scene argument and --set, shared with run).
template <class Options>
CLI::App* add_scene_command(CLI::App& parent, const SceneCommandHelp& help, SceneCheck check,
                            void (*add_options)(CLI::App&, Options&), void (*run)(const Scene&, const Options&)) {
  auto options = std::make_shared<Options>();
  CLI::App* cmd = add_scene_command(parent, help, check, [options, run](const Scene& scene) { run(scene, *options); });
  add_options(*cmd, *options);
  return cmd;
}

}  // namespace railjoint::cli
