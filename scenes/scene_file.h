#pragma once
// Reading scene files: TOML with [joint] and [wheel] sections in SI units
// (angles as `_deg` keys), plus `--set section.key=value` overrides.

#include <string>
#include <vector>

#include "scenes/scene.h"

namespace railjoint {

/// Reads and checks a scene file, applying overrides of the form
/// "section.key=value" (value in TOML syntax; a bare word is taken as a string).
/// Throws InputError naming the file, the key and the allowed range.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

/// Same as load_scene, from text; `name` stands in for the file in messages.
Scene parse_scene(const std::string& toml_text, const std::string& name,
                  const std::vector<std::string>& overrides = {});

}  // namespace railjoint
