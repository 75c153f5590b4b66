#pragma once
// A scene as a parsed TOML tree: for those who read many variants of one
// scene from one parse (a sweep's cases) or make a scene's text from keys
// (Python). Apart from scene_file.h so that only they see toml++; defined
// beside the reader in scene_file.cpp.

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "scenes/scene_file.h"

namespace railjoint {

/// The whole TOML text of a scene (or a sweep file), parsed once; throws
/// InputError naming `name` for text that is not TOML.
toml::table parse_scene_tree(const std::string& toml_text, const std::string& name);

/// The scene's TOML tree as parse_scene reads it: `unsets` removed, then
/// `overrides` set (a scene made in Python with --set keys, as the base of a
/// sweep). Throws InputError naming `name` for text that is not TOML or a bad
/// --set or --unset; the keys themselves are checked when the tree is read.
/// Its profile paths are made absolute (`profiles`, as parse_scene's), so the
/// tree reads the same files from any folder.
toml::table scene_tree(const std::string& toml_text, const std::string& name,
                       const std::vector<std::string>& overrides, const std::vector<std::string>& unsets,
                       const ProfileSource* profiles = nullptr);

/// Reads a parsed scene with typed overrides applied to a copy of it: exactly
/// load_scene without the file and the parse, for reading many variants of one
/// scene (sweeps), and without recording the keys read (Scene::resolved stays
/// empty: docs/benchmarks.md, its cost). Throws InputError naming
/// `name`, the key and the allowed range. The tree's and the overrides'
/// profile paths are absolute (anchor_profile_paths, scenes/profile_files.h);
/// each file is read once into `profiles` (absent: files of this read's own).
Scene read_scene_tree(const toml::table& root, const std::string& name, const std::vector<SceneOverride>& overrides,
                      SceneCheck check = SceneCheck::model, ProfileFiles* profiles = nullptr);

}  // namespace railjoint
