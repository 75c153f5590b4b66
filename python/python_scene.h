#pragma once
// A scene as the Python module holds it: what it was made from (a TOML text
// and the name that stands for its file in messages, --set overrides,
// --unset keys) and the scenes the reader made of it, one per check a command
// asks for (scenes/scene_file.h: `pressure` reads the keys only, `analytic`
// and `simulate` check the case against the kinematic model). Every read is
// the CLI's parse_scene, so keys, defaults, units and messages are its own.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "scenes/scene.h"
#include "scenes/scene_file.h"
#include "support/input_error.h"

namespace railjoint::python {

struct SceneSource {
  std::string text;                    ///< TOML, as in a scene file
  std::string name;                    ///< the file as named, or "scene": names the file in messages
  std::vector<std::string> overrides;  ///< "section.key=value", as --set
  std::vector<std::string> unsets;     ///< "section.key", as --unset
};

class PythonScene {
 public:
  /// Reads the keys (SceneCheck::keys_only): a bad key, type or range throws
  /// InputError here, as the CLI refuses it before any command runs.
  explicit PythonScene(SceneSource source);
  /// The same, its relative profile paths read from the folders given (an
  /// unpickled scene: those of the scene it was pickled from, whatever the
  /// current folder is when it is unpickled).
  PythonScene(SceneSource source, const std::filesystem::path& scene_folder,
              const std::filesystem::path& overrides_folder);

  const SceneSource& source() const { return source_; }
  /// The scene read with its keys checked only (what `pressure` reads).
  const Scene& keys() const { return *keys_only_; }
  /// The scene read with `check` (read on first use, then kept): throws
  /// InputError for a case outside the kinematic model, as `analytic` does.
  std::shared_ptr<const Scene> checked(SceneCheck check) const;
  /// The scene's TOML text with the overrides and unsets applied and its
  /// profile paths absolute: the base of a sweep made from this scene.
  std::string resolved_text() const;
  /// Its profile files, as read when the Scene was made (a sweep of it reads no other).
  const std::shared_ptr<ProfileFiles>& profile_files() const { return profiles_.files; }
  /// Where its relative profile paths are read from: the scene file's
  /// folder, and the folder that was current for its overrides.
  const std::filesystem::path& scene_folder() const { return profiles_.scene_folder; }
  const std::filesystem::path& overrides_folder() const { return profiles_.overrides_folder; }

 private:
  SceneSource source_;
  /// Fixed when the Scene is made: a relative path is its file's (or, in an
  /// override, the folder current then), read once, whatever os.chdir does later.
  ProfileSource profiles_;
  std::shared_ptr<const Scene> keys_only_;
  mutable std::shared_ptr<const Scene> model_;
  mutable std::shared_ptr<const Scene> geometry_;
  mutable std::shared_ptr<const Scene> simulation_;
};

/// f(), with an InputError that names no file raised again naming the
/// scene's: the checks of the model, the simulation and the local model know
/// keys, not files (as the CLI's scene commands do, scenes/cli/scene_command.h).
template <class F>
auto naming_scene_file(const Scene& scene, F f) {
  try {
    return f();
  } catch (const InputError& error) {
    if (!error.file().empty()) throw;
    throw error.in_file(scene.file);
  }
}

}  // namespace railjoint::python
