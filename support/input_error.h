#pragma once
// Bad input: a parameter combination the model cannot describe (e.g.
// |y_w| > b_t, u0 >= R), a bad key in a scene file or a --set override, a
// flag. Carries the key ("section.key", or the command-line option) and, once
// it is known, the file. The code that checks a value rarely knows where it
// came from: the scene loader and each scene command add the file
// (in_file()), and the CLI catches the error once and prints one line.
// Broken invariants inside the code use assert instead.

#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

namespace railjoint {

/// A length for an InputError message: "%.6g m", e.g. "0.0176 m".
inline std::string metres_text(double value_m) {
  char text[48];
  std::snprintf(text, sizeof text, "%.6g m", value_m);
  return text;
}

/// `text` as one printable line: control characters (a newline or an escape
/// in a key, a value or a path the user typed) are written as \n, \r, \t or
/// \xHH, and the C1 controls of UTF-8 (U+0080..U+009F, e.g. the one-byte
/// CSI U+009B) as \u00HH, so an error stays on one line and nothing in it
/// drives the terminal. Printable UTF-8 passes unchanged; escaping twice
/// changes nothing more.
inline std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  char code[8];
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      std::snprintf(code, sizeof code, "\\x%02x", c);
      out += code;
    } else if (c == 0xc2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
               static_cast<unsigned char>(text[i + 1]) <= 0x9f) {
      std::snprintf(code, sizeof code, "\\u00%02x", static_cast<unsigned char>(text[++i]));
      out += code;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

class InputError : public std::invalid_argument {
 public:
  /// Where the file is not known (models, geometry, sim, renders): what()
  /// is the message alone until in_file() names the file.
  InputError(std::string key, const std::string& message)
      : std::invalid_argument(one_line(message)), key_(std::move(key)), message_(message) {}

  /// what() is "file: key 'key': message" (no key: "file: message"), on one
  /// line (one_line()); file(), key() and message() keep the text as given.
  InputError(std::string file, std::string key, const std::string& message)
      : std::invalid_argument(format(file, key, message)),
        file_(std::move(file)),
        key_(std::move(key)),
        message_(message) {}

  const std::string& file() const { return file_; }  ///< "" until named
  const std::string& key() const { return key_; }
  const std::string& message() const { return message_; }

  /// The same error naming the file its values came from.
  InputError in_file(std::string file) const { return InputError(std::move(file), key_, message_); }

 private:
  static std::string format(const std::string& file, const std::string& key, const std::string& message) {
    std::string text = file.empty() ? std::string("input") : file;
    if (!key.empty()) text += ": key '" + key + "'";
    return one_line(text + ": " + message);
  }
  std::string file_;
  std::string key_;
  std::string message_;
};

}  // namespace railjoint
