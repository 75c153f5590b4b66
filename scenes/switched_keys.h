#pragma once
// Keys that only apply with one value of a switch (contact_patch.size =
// "given" takes length and width, track.model = "discrete" its beam): a key
// the switch makes meaningless would change nothing, so it is refused, never
// silently ignored. The error blames the one of the two the user typed
// last: the key, or the switch when a --set turned it under keys the scene
// file gives (--set contact_patch.size=hertz on a file with a length).

#include <initializer_list>
#include <span>
#include <string_view>

#include "scenes/section_reader.h"
#include "sim/setting_checks.h"

namespace railjoint {

/// Unless `applies`, throws InputError for the first of `keys` (within the
/// section) the section gives, with `why` ("only applies to size =
/// \"given\" (...)"), or for `switch_key` when the user typed it after all
/// of them, naming them and how to drop them. The keys are the section's
/// all the same: a typo of one is named as such (SectionReader::expect).
void refuse_keys_unless(SectionReader& in, const KeyOrigins& origins, bool applies,
                        std::span<const std::string_view> keys, std::string_view switch_key, std::string_view why);
inline void refuse_keys_unless(SectionReader& in, const KeyOrigins& origins, bool applies,
                               std::initializer_list<std::string_view> keys, std::string_view switch_key,
                               std::string_view why) {
  refuse_keys_unless(in, origins, applies, std::span(keys.begin(), keys.size()), switch_key, why);
}

}  // namespace railjoint
