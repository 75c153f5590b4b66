#pragma once
// A scene as loaded from a TOML file: the read-only description of one run.
// Each optional section switches on the part of the program that needs it
// (no [render], no GL context).

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "models/impact_prediction.h"
#include "models/local_model_settings.h"
#include "models/parameters.h"
#include "renders/render_settings.h"
#include "scenes/resolved_keys.h"
#include "sim/setting_checks.h"
#include "sim/sim_settings.h"

namespace railjoint {

struct CrossingModel;  // sim/crossing_model.h

struct Scene {
  std::string file;         ///< where it was read from (for messages)
  std::string name;         ///< optional `name` key, else the file stem
  std::string description;  ///< optional `description` key
  JointParams joint;
  WheelParams wheel;
  SimSettings sim;  ///< [sim] section (defaults when absent)
  std::optional<RenderSettings> render;  ///< [render] section; absent = no GL context
  ContactPatchSettings contact_patch;    ///< [contact_patch] section: the local model (defaults when absent)
  /// The kinematic model's answer for joint and wheel, computed once when the
  /// scene is checked against the model (SceneCheck::model; absent for a
  /// geometry-only check) and handed on to whoever reports it.
  std::optional<ImpactPrediction> prediction;
  /// The crossing a simulation runs, checked and built once where the scene
  /// is read (SceneCheck::simulation; empty otherwise): joint, wheels,
  /// settings, predictions, rails, start. `simulate` and `render` run it,
  /// report it and draw it; nothing below checks the raw sections again.
  std::shared_ptr<const CrossingModel> crossing;
  /// The keys the file or a --set override gave ("joint.length", "sim.slop";
  /// top-level keys as "name"): the others hold defaults. A command refuses
  /// a key that changes nothing in its mode, blames the key the user set
  /// when two disagree, and derives what the user left out (the rail length
  /// a run needs when joint.length is not given).
  std::set<std::string> given_keys;
  bool given(const std::string& key) const { return given_keys.contains(key); }
  /// The keys among them that --set (or a sweep's axis) gave: typed after
  /// the file, so a conflict with a key of the file blames these.
  std::set<std::string> command_line_keys;
  KeyOrigin origin(const std::string& key) const {
    return command_line_keys.contains(key) ? KeyOrigin::command_line
           : given(key)                    ? KeyOrigin::file
                                           : KeyOrigin::default_value;
  }
  /// Every key read, section by section, with the value used: what the
  /// reports echo as the scene they ran under (scenes/report/scene_json.h).
  /// Empty for a sweep's cases (read_scene_tree).
  std::vector<ResolvedSection> resolved;
};

}  // namespace railjoint
