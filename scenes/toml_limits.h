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

#include <toml++/toml.h>

namespace railjoint {

/// The largest scene text read [bytes]: a scene is a few hundred bytes.
inline constexpr std::size_t kMaxSceneBytes = 1 << 20;

/// The most dots in keys, '[' and '{' one line may hold outside strings and
/// comments, counting the '[' and '{' still open from the lines before it (a
/// value's decimal points nest nothing). Every level of nesting needs one of
/// them, so no text that passes nests deeper than 1000 levels, a small part
/// of the parser's stack; a scene line holds a handful.
inline constexpr int kMaxNestingMarksPerLine = 1000;

/// toml::parse(text, source) made safe for toml++ 3.3. First refused, with
/// an InputError naming `file` and `key` (empty for a whole scene;
/// "section.key" for a --set value): a text longer than kMaxSceneBytes, a
/// line with more nesting marks than allowed, a non-ASCII character where
/// toml++ asks whether it is whitespace (outside strings and comments, after
/// a quote where no string can start, after a backslash in a multi-line
/// string: toml_limits.cpp). Then the text's structure is parsed with every
/// non-ASCII character replaced by '~' (legal only in strings and comments),
/// so a document toml++ would read on into an error never shows it one;
/// only a document whose structure holds is parsed as it is. Throws
/// toml::parse_error like toml::parse (from the stand-in: same lines and
/// columns, '~' for the character).
toml::table parse_toml(std::string_view text, std::string_view source, const std::string& file, const std::string& key);

}  // namespace railjoint
