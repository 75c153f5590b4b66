#include "scenes/report/scene_json.h"

namespace railjoint {

nlohmann::json scene_json(const Scene& scene) {
  nlohmann::json j;
  j["file"] = scene.file;
  j["name"] = scene.name;
  j["description"] = scene.description;
  nlohmann::json derived = nlohmann::json::array();
  for (const ResolvedSection& section : scene.resolved) {
    nlohmann::json& keys = j[section.name] = nlohmann::json::object();
    for (const ResolvedKey& key : section.keys) {
      std::visit([&](const auto& value) { keys[key.key] = value; }, key.value);
      if (key.source == KeySource::derived) derived.push_back(section.name + "." + key.key);
    }
  }
  j["derived"] = derived;
  return j;
}

}  // namespace railjoint
