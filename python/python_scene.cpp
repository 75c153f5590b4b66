#include "python_scene.h"
#include "scenes/profile_files.h"

#include <sstream>

#include <toml++/toml.h>

#include "scenes/scene_tree.h"

namespace railjoint::python {

namespace {

std::shared_ptr<const Scene> read(const SceneSource& source, SceneCheck check, const ProfileSource& profiles) {
  return std::make_shared<const Scene>(
      parse_scene(source.text, source.name, source.overrides, check, source.unsets, &profiles));
}

}  // namespace

PythonScene::PythonScene(SceneSource source)
    : source_(std::move(source)), profiles_(profile_source_now(source_.name)),
      keys_only_(read(source_, SceneCheck::keys_only, profiles_)) {}

PythonScene::PythonScene(SceneSource source, const std::filesystem::path& scene_folder,
                         const std::filesystem::path& overrides_folder)
    : source_(std::move(source)),
      profiles_{scene_folder, overrides_folder, std::make_shared<ProfileFiles>()},
      keys_only_(read(source_, SceneCheck::keys_only, profiles_)) {}

std::shared_ptr<const Scene> PythonScene::checked(SceneCheck check) const {
  // Callers hold the GIL: the first use reads, later ones share the scene.
  switch (check) {
    case SceneCheck::keys_only:
      return keys_only_;
    case SceneCheck::model:
      if (!model_) model_ = read(source_, check, profiles_);
      return model_;
    case SceneCheck::geometry:
      if (!geometry_) geometry_ = read(source_, check, profiles_);
      return geometry_;
    case SceneCheck::simulation:
      if (!simulation_) simulation_ = read(source_, check, profiles_);
      return simulation_;
  }
  return keys_only_;
}

std::string PythonScene::resolved_text() const {
  const toml::table tree = scene_tree(source_.text, source_.name, source_.overrides, source_.unsets, &profiles_);
  // The text as given when nothing changed it (a sweep's fingerprint of its base stays the file's).
  if (source_.overrides.empty() && source_.unsets.empty() && tree == parse_scene_tree(source_.text, source_.name)) {
    return source_.text;
  }
  std::ostringstream text;
  text << tree;
  return text.str();
}

}  // namespace railjoint::python
