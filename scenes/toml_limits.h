#pragma once
// Limits on the TOML text a scene (or a --set value) may hand the TOML parser.
// toml++ (Debian's 3.3, a shared library, so its own limits cannot be
// changed here) recurses once per level of a dotted key or table header
// (a.b.c... = 1) and overflowed the 8 MB stack at about 30,000 levels: a
// scene file must never crash the program. A scene nests two levels
// ([section] and key), so the text is checked before it is parsed.

#include <cstddef>
#include <string>
#include <string_view>

namespace railjoint {

/// The largest scene text read [bytes]: a scene is a few hundred bytes.
inline constexpr std::size_t kMaxSceneBytes = 1 << 20;

/// The most dots, '[' and '{' one line may hold outside strings and
/// comments. Every level of nesting needs one of them on the line that
/// creates it (a key or a header cannot span lines, nor, in TOML 1.0, an
/// inline table; arrays that span lines stop at toml++'s own 256 levels),
/// so no text that passes nests deeper than 1000 + 256 levels: 0.4 MB of
/// the parser's stack at the 270 bytes a level measured here. A scene line
/// holds a handful (a number's decimal point, a header's brackets).
inline constexpr int kMaxNestingMarksPerLine = 1000;

/// Throws InputError naming `file` and `key` (empty for a whole scene;
/// "section.key" for a --set value) when `text` is longer than
/// kMaxSceneBytes or a line holds more nesting marks than allowed.
void check_toml_limits(std::string_view text, const std::string& file, const std::string& key);

}  // namespace railjoint
