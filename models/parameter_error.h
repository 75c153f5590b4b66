#pragma once
// A parameter combination the model cannot describe (e.g. |y_w| > b_t, u0 >= R).
// Carries the scene key ("section.key") so the CLI can name it; the scene
// loader adds the file name.

#include <cstdio>
#include <stdexcept>
#include <string>

namespace railjoint {

/// A length for a ParameterError message: "%.6g m", e.g. "0.0176 m".
inline std::string metres_text(double value_m) {
  char text[48];
  std::snprintf(text, sizeof text, "%.6g m", value_m);
  return text;
}

class ParameterError : public std::invalid_argument {
 public:
  ParameterError(std::string key, const std::string& message)
      : std::invalid_argument(message), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

}  // namespace railjoint
