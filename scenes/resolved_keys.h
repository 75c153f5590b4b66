#pragma once
// The keys of a scene as a run used them: what the file or --set gave, the
// default of every key left out, and the values derived from others (the
// rail length a run needs). The JSON reports echo them under "scene", so an
// output says what it ran under (scenes/report/scene_json.h).

#include <string>
#include <variant>
#include <vector>

namespace railjoint {

/// A value of a scene key as TOML types it.
using SceneValue = std::variant<bool, long long, double, std::string>;

enum class KeySource { given, default_value, derived };

/// One key of a section, its value in the file's units (theta_deg in degrees).
struct ResolvedKey {
  std::string key;  ///< within its section: "theta_deg"
  SceneValue value;
  KeySource source = KeySource::given;
};

/// The keys of one [section] in the order they were read.
struct ResolvedSection {
  std::string name;
  std::vector<ResolvedKey> keys;
};

}  // namespace railjoint
