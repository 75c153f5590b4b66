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

namespace railjoint {

/// A length for an InputError message: "%.6g m", e.g. "0.0176 m".
inline std::string metres_text(double value_m) {
  char text[48];
  std::snprintf(text, sizeof text, "%.6g m", value_m);
  return text;
}

class InputError : public std::invalid_argument {
 public:
  /// Where the file is not known (models, geometry, sim, renders): what()
  /// is the message alone until in_file() names the file.
  InputError(std::string key, const std::string& message)
      : std::invalid_argument(message), key_(std::move(key)), message_(message) {}

  /// what() is "file: key 'key': message" (no key: "file: message").
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
    return text + ": " + message;
  }
  std::string file_;
  std::string key_;
  std::string message_;
};

}  // namespace railjoint
