#include "scenes/toml_limits.h"

#include "models/input_error.h"

namespace railjoint {

namespace {

enum class Lexeme { text, comment, basic, literal, multiline_basic, multiline_literal };

bool starts_with_at(std::string_view text, std::size_t i, std::string_view prefix) {
  return text.substr(i, prefix.size()) == prefix;
}

}  // namespace

void check_toml_limits(std::string_view text, const std::string& file, const std::string& key) {
  if (text.size() > kMaxSceneBytes) {
    throw InputError(file, key,
                     "is " + std::to_string(text.size()) + " bytes of TOML; a scene is a few hundred (at most " +
                         std::to_string(kMaxSceneBytes) + ")");
  }
  // A lexer just good enough to skip strings and comments: it never
  // decides whether the text is valid TOML (toml++ does), only that a line
  // cannot nest deeper than the limit.
  Lexeme state = Lexeme::text;
  int marks = 0;
  int line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      marks = 0;
      if (state == Lexeme::comment || state == Lexeme::basic || state == Lexeme::literal) state = Lexeme::text;
      continue;
    }
    switch (state) {
      case Lexeme::text:
        if (c == '#') {
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
        } else if ((c == '.' || c == '[' || c == '{') && ++marks > kMaxNestingMarksPerLine) {
          throw InputError(file, key,
                           "line " + std::to_string(line) + " holds more than " +
                               std::to_string(kMaxNestingMarksPerLine) +
                               " dots, brackets and braces outside strings and comments: it could nest deeper "
                               "than the TOML parser can read (a scene nests two levels, [section] and key)");
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
        if (c == '\\' && i + 1 < text.size() && text[i + 1] != '\n') {
          ++i;
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

}  // namespace railjoint
