#include "scenes/cli/scene_command.h"

#include <memory>
#include <vector>

#include "models/input_error.h"

namespace railjoint::cli {

namespace {
struct SceneArguments {
  std::string path;
  std::vector<std::string> overrides;
};
}  // namespace

CLI::App* add_scene_command(CLI::App& parent, const SceneCommandHelp& help, SceneCheck check,
                            std::function<void(const Scene&)> run) {
  auto arguments = std::make_shared<SceneArguments>();
  CLI::App* cmd = parent.add_subcommand(help.name, help.description);
  cmd->add_option("scene", arguments->path, help.scene)->required();
  cmd->add_option("--set", arguments->overrides,
                  "Override a scene key: section.key=value (repeatable), e.g. " + help.set_example);
  cmd->callback([arguments, check, run = std::move(run)] {
    const Scene scene = load_scene(arguments->path, arguments->overrides, check);
    try {
      run(scene);
    } catch (const InputError& error) {
      if (!error.file().empty()) throw;
      throw error.in_file(scene.file);
    }
  });
  return cmd;
}

}  // namespace railjoint::cli
