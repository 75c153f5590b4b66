#pragma once
// Bad user input (a scene file, a --set override, a flag). Thrown with the
// file, the key and what is allowed; caught once in the CLI and printed as one
// line. Broken invariants inside the code use assert instead.

#include <stdexcept>
#include <string>

namespace railjoint {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string key, const std::string& message)
      : std::runtime_error(format(file, key, message)), file_(std::move(file)), key_(std::move(key)) {}

  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }

 private:
  static std::string format(const std::string& file, const std::string& key, const std::string& message) {
    std::string text = file.empty() ? std::string("input") : file;
    if (!key.empty()) text += ": key '" + key + "'";
    return text + ": " + message;
  }
  std::string file_;
  std::string key_;
};

}  // namespace railjoint
