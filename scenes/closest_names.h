#pragma once
// Names ordered by how close they are to a mistyped one (edit distance), for
// the errors of an unknown key or command: "did you mean 'speed'?".

#include <string>
#include <string_view>
#include <vector>

namespace railjoint {

/// `names` ordered closest to `typed` first (Levenshtein distance, ties by
/// name), duplicates removed.
std::vector<std::string> closest_first(std::string_view typed, std::vector<std::string> names);

/// " (did you mean 'x'?)" when a name is a likely typo of `typed` (at most
/// a third of its letters edited, at least one), else "".
std::string did_you_mean(std::string_view typed, const std::vector<std::string>& names);

}  // namespace railjoint
