#include "scenes/cli/scene_command.h"

#include <algorithm>
#include <memory>
#include <vector>

#include "support/input_error.h"

namespace railjoint::cli {

namespace {
struct SceneArguments {
  std::string path;
  std::vector<std::string> overrides;
  std::vector<std::string> unsets;
};

// `analytic --set render.view=top` changed nothing and said nothing.
void refuse_unread_overrides(const std::string& command, const std::vector<std::string>& sections,
                             const std::string& path, const std::vector<std::string>& overrides) {
  for (const std::string& assignment : overrides) {
    const SceneOverride change = parse_override(path, assignment);
    if (std::find(sections.begin(), sections.end(), change.section) != sections.end()) continue;
    // A mistyped section is the scene reader's to name, with the one meant.
    if (!is_scene_section(change.section)) continue;
    std::string read;
    for (const std::string& section : sections) read += (read.empty() ? "[" : ", [") + section + "]";
    throw InputError(path, change.section + "." + change.key,
                     command + " does not read [" + change.section + "], so this --set changes nothing; it reads " +
                         read);
  }
}
}  // namespace

CLI::App* add_scene_command(CLI::App& parent, const SceneCommandHelp& help, SceneCheck check,
                            std::function<void(const Scene&)> run) {
  auto arguments = std::make_shared<SceneArguments>();
  CLI::App* cmd = parent.add_subcommand(help.name, help.description);
  cmd->add_option("scene", arguments->path, help.scene)->required();
  cmd->add_option("--set", arguments->overrides,
                  "Override a scene key: section.key=value (repeatable), e.g. " + help.set_example +
                      "; a profile file (wheel.profile=tread.csv) is relative to the current folder, one in the "
                      "scene file to the scene file's");
  cmd->add_option("--unset", arguments->unsets,
                  "Drop a key the scene file gives, so it takes its default: section.key (repeatable)");
  cmd->callback([arguments, check, run = std::move(run), name = help.name, sections = help.sections_read] {
    if (!sections.empty()) refuse_unread_overrides(name, sections, arguments->path, arguments->overrides);
    const Scene scene = load_scene(arguments->path, arguments->overrides, check, arguments->unsets);
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
