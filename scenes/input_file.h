#pragma once
// Reading an input file (a scene, a sweep) whole, with the one-line errors
// of every other bad input: the file, and what is wrong with it.

#include <string>

namespace railjoint {

/// The file's text. `kind` names it in messages ("scene", "sweep").
/// Throws InputError: no such file, not a regular file, larger than
/// kMaxSceneBytes, cannot be opened, or a read fails (never an empty text in
/// place of an unreadable file).
std::string read_input_file(const std::string& path, const std::string& kind);

}  // namespace railjoint
