#pragma once
// Reading scene files: TOML with [joint] and [wheel] sections in SI units
// (angles as `_deg` keys), plus `--set section.key=value` overrides.

#include <string>
#include <vector>

#include "scenes/scene.h"

namespace railjoint {

/// What a scene must describe besides valid keys: a case the kinematic model
/// covers (every command that predicts or simulates an impact), or only
/// geometry that exists (`mesh`: a level joint with an end post, or a gap the
/// wheel would drop into, are still rails to export), or nothing more (the
/// local model of `pressure`, which checks its own combinations).
enum class SceneCheck { model, geometry, keys_only };

/// Reads and checks a scene file, applying overrides of the form
/// "section.key=value" (value in TOML syntax; a bare word is taken as a string).
/// Throws InputError naming the file, the key and the allowed range.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {},
                 SceneCheck check = SceneCheck::model);

/// Same as load_scene, from text; `name` stands in for the file in messages.
Scene parse_scene(const std::string& toml_text, const std::string& name,
                  const std::vector<std::string>& overrides = {}, SceneCheck check = SceneCheck::model);

}  // namespace railjoint
