#pragma once
// Reading scene files: TOML with [joint] and [wheel] sections in SI units
// (angles as `_deg` keys), plus `--set section.key=value` overrides.

#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "scenes/scene.h"

namespace railjoint {

class ProfileFiles;
struct CrossingPredictions;  // sim/crossing_model.h

/// Where the profile files a scene names are found, and where each is kept
/// once read (scenes/profile_files.h): a relative path in the scene's text is
/// relative to the scene file's folder, one in an override (`--set`) to the
/// folder the override was typed in.
struct ProfileSource {
  std::filesystem::path scene_folder;
  std::filesystem::path overrides_folder;
  std::shared_ptr<ProfileFiles> files;
};

/// The source of the scene file `name` as of now: its folder and the
/// current one (absolute), and files of its own.
ProfileSource profile_source_now(const std::string& name);

/// What a scene must describe besides valid keys: a case the kinematic model
/// covers (every command that predicts or simulates an impact), or only
/// geometry that exists (`mesh`: a level joint with an end post, or a gap the
/// wheel would drop into, are still rails to export), or nothing more (the
/// local model of `pressure`, which checks its own combinations). A
/// simulation: the model's case, and the crossing the simulation runs,
/// checked and built once (Scene::crossing), its predictions made once.
enum class SceneCheck { model, geometry, keys_only, simulation };

/// Reads and checks a scene file, applying overrides of the form
/// "section.key=value" (value in TOML syntax; a bare word is taken as a string).
/// Throws InputError naming the file, the key and the allowed range.
/// `unsets` ("section.key") are removed from the file's keys first, so they
/// take their defaults (--unset); a key the file does not give is an error.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {},
                 SceneCheck check = SceneCheck::model, const std::vector<std::string>& unsets = {});

/// Same as load_scene, from text; `name` stands in for the file in messages.
/// `profiles` absent: profile_source_now(name).
Scene parse_scene(const std::string& toml_text, const std::string& name,
                  const std::vector<std::string>& overrides = {}, SceneCheck check = SceneCheck::model,
                  const std::vector<std::string>& unsets = {}, const ProfileSource* profiles = nullptr);

/// joint.length when the scene does not give it (load_scene does both for
/// SceneCheck::model, the first also for geometry): at least what the
/// kinematic model needs to carry the wheel on both rails, and then what a
/// simulation of the scene needs for its approach and run-out
/// (rail_length_needed_m), never below the default 1 m nor above 100 m. One
/// rule for every command, and for a sweep's cases, which are read with
/// SceneCheck::keys_only: each derives the minimum, and a simulating
/// model the simulated length in scene_crossing, as `simulate` does.
void derive_minimum_rail_length(Scene& scene);

/// The crossing a simulation of the scene runs, checked and built once: the
/// predictions (`prediction`, the scene wheel's, already made), the rails
/// derived from them (their length into `rail_length_m`), then the model,
/// its inputs checked blaming the key `origins` says was typed last. A
/// prediction the simulated wheel cannot have is left to the model's build,
/// which checks the inputs first and so blames the right key.
std::shared_ptr<const CrossingModel> scene_crossing(const Scene& scene, const ImpactPrediction& prediction,
                                                    const KeyOrigins& origins, double& rail_length_m);

/// What SceneCheck::simulation adds, for a scene read with another check
/// that turns out to need its force run (`pressure` with
/// contact_patch.normal_force = "forces"): the rails derived, the
/// prediction, the checked crossing in Scene::crossing. InputError names the file.
void check_for_simulation(Scene& scene);

/// One scene key set to a typed value: what `--set section.key=value` becomes
/// once its text is parsed, and what a sweep's axis gives for a case.
struct SceneOverride {
  std::string section;
  std::string key;
  SceneValue value;
};

/// The text of `--set section.key=value`, parsed (a bare word is a string).
/// Throws InputError naming `file` and the assignment.
SceneOverride parse_override(const std::string& file, const std::string& assignment);

/// Whether a scene file may hold this section ([joint], [wheel], ...).
bool is_scene_section(const std::string& name);

}  // namespace railjoint
