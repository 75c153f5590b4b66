#include "scenes/toml_limits.h"

#include <algorithm>

#include "support/input_error.h"

namespace railjoint {

namespace {

enum class Lexeme { text, comment, basic, literal, multiline_basic, multiline_literal };

bool starts_with_at(std::string_view text, std::size_t i, std::string_view prefix) {
  return text.substr(i, prefix.size()) == prefix;
}

bool is_non_ascii(char c) { return (static_cast<unsigned char>(c) & 0x80) != 0; }

// Where toml++ 3.3 asks whether a character is whitespace (outside strings
// and comments, and after a backslash in a multi-line string),
// a non-ASCII one can reach TOML_UNREACHABLE in is_non_ascii_horizontal_whitespace
// (upstream marzer/tomlplusplus issue 190, fixed after 3.3): undefined
// behaviour. TOML 1.0 allows non-ASCII text only in strings and comments, so
// it is refused anywhere else before the parser sees it.
[[noreturn]] void refuse_non_ascii(const std::string& file, const std::string& key, int line, const char* where) {
  throw InputError(file, key,
                   "line " + std::to_string(line) + ": a non-ASCII character " + where +
                       " (TOML allows them only inside strings and comments)");
}

void check_toml_limits(std::string_view text, const std::string& file, const std::string& key) {
  if (text.size() > kMaxSceneBytes) {
    throw InputError(file, key,
                     "is " + std::to_string(text.size()) + " bytes of TOML; a scene is a few hundred (at most " +
                         std::to_string(kMaxSceneBytes) + ")");
  }
  // A lexer just good enough to skip strings and comments: it never
  // decides whether the text is valid TOML (toml++ does), only that a line
  // cannot nest deeper than the limit and where non-ASCII text may stand. A
  // quote opens a string only where TOML has one (a key: at a line's start,
  // after '.', '{' or ','; a value: after '=', '[' or ','): elsewhere (the
  // fuzzer's `name = +"...`) toml++ reads on as a bad value, asking of each
  // character whether it is whitespace, so a non-ASCII one there is refused.
  Lexeme state = Lexeme::text;
  // A line's marks start from the brackets and braces still open from the
  // lines before it: in TOML 1.0 an array inside an inline table may span
  // lines, and each of its lines can open a dotted key ~1000 levels deep,
  // which toml++'s ~table() unwinds by recursion. Which brackets and braces are open ('[' array or header, '{' inline
  // table), and whether the lexer stands in a key: only a key's dots nest.
  // A value's dots (decimal points: a list of 1000 numbers on one line) never
  // reach the parser's recursion, so they are not counted.
  std::string open_kinds;
  bool in_key = true;
  int open = 0;
  int marks = 0;
  int line = 1;
  char previous = '\n';  // the last character outside strings and comments but blanks
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      marks = open;
      in_key = open_kinds.empty() || open_kinds.back() == '{';
      if (state == Lexeme::comment || state == Lexeme::basic || state == Lexeme::literal) state = Lexeme::text;
      if (state == Lexeme::text) previous = '\n';
      continue;
    }
    const bool string_may_start = std::string_view("\n.{,=[").find(previous) != std::string_view::npos;
    if (state == Lexeme::text && c != ' ' && c != '\t' && c != '\r') previous = c;
    switch (state) {
      case Lexeme::text:
        if (is_non_ascii(c)) refuse_non_ascii(file, key, line, "outside a string or comment");
        if ((c == '"' || c == '\'') && !string_may_start) {
          // A stray quote: not a string, read on as text.
        } else if (c == '#') {
          state = Lexeme::comment;
        } else if (starts_with_at(text, i, "\"\"\"")) {
          state = Lexeme::multiline_basic;
          i += 2;
        } else if (starts_with_at(text, i, "'''")) {
          state = Lexeme::multiline_literal;
          i += 2;
        } else if (c == '"') {
          state = Lexeme::basic;
        } else if (c == '\'') {
          state = Lexeme::literal;
        } else if (c == ']' || c == '}') {
          open = std::max(0, open - 1);
          if (!open_kinds.empty()) open_kinds.pop_back();
          in_key = false;  // after an array or inline table: a value ends, or a header
        } else if (c == '=') {
          in_key = false;
        } else if (c == ',') {
          in_key = !open_kinds.empty() && open_kinds.back() == '{';
        } else if ((c == '.' && in_key) || c == '[' || c == '{') {
          if (c != '.') {
            ++open;
            if (open_kinds.size() < static_cast<std::size_t>(kMaxNestingMarksPerLine) + 1) open_kinds += c;
            if (c == '{') in_key = true;  // an inline table's first key
          }
          if (++marks > kMaxNestingMarksPerLine) {
            throw InputError(file, key,
                             "line " + std::to_string(line) + " holds more than " +
                                 std::to_string(kMaxNestingMarksPerLine) +
                                 " dots, brackets and braces outside strings and comments (with those still open "
                                 "from the lines before): it could nest deeper than the TOML parser can read (a "
                                 "scene nests two levels, [section] and key)");
          }
        }
        break;
      case Lexeme::comment:
        break;
      case Lexeme::basic:
        if (c == '\\' && i + 1 < text.size() && text[i + 1] != '\n') {
          ++i;  // an escaped quote or backslash
        } else if (c == '"') {
          state = Lexeme::text;
        }
        break;
      case Lexeme::literal:
        if (c == '\'') state = Lexeme::text;
        break;
      case Lexeme::multiline_basic:
        if (c == '\\') {
          // The parser asks of what follows a backslash whether it is
          // whitespace (a line-ending backslash skips blanks and newlines).
          const std::size_t next = text.find_first_not_of(" \t\r\n", i + 1);
          if (next != std::string_view::npos && is_non_ascii(text[next])) {
            const auto lines_skipped = std::count(text.begin() + static_cast<long>(i), text.begin() + static_cast<long>(next), '\n');
            refuse_non_ascii(file, key, line + static_cast<int>(lines_skipped),
                             "after a backslash in a multi-line string");
          }
          if (i + 1 < text.size() && text[i + 1] != '\n') ++i;  // an escaped quote or backslash
        } else if (starts_with_at(text, i, "\"\"\"")) {
          state = Lexeme::text;
          i += 2;
        }
        break;
      case Lexeme::multiline_literal:
        if (starts_with_at(text, i, "'''")) {
          state = Lexeme::text;
          i += 2;
        }
        break;
    }
  }
}

}  // namespace

toml::table parse_toml(std::string_view text, std::string_view source, const std::string& file, const std::string& key) {
  check_toml_limits(text, file, key);
  if (std::any_of(text.begin(), text.end(), is_non_ascii)) {
    std::string stand_in;
    stand_in.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (!is_non_ascii(text[i])) {
        stand_in += text[i];
        continue;
      }
      stand_in += '~';  // one for each character: a UTF-8 lead byte and its continuation bytes
      while (i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xC0) == 0x80) ++i;
    }
    const toml::table structure = toml::parse(stand_in, source);  // throws where the structure fails
    (void)structure;
  }
  return toml::parse(text, source);
}

}  // namespace railjoint
