#pragma once
// Small text helpers the study reports share: printf-style numbers, CSV
// quoting and joining.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace railjoint {

/// One number through a printf pattern, e.g. format_number("%.3g mm", x).
inline std::string format_number(const char* pattern, double value) {
  char text[96];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

/// format_number, or `missing` for NaN or infinity (a closed form outside
/// the range where it has a real value, a relative error against no jump).
inline std::string format_finite(const char* pattern, double value, const char* missing = "n/a") {
  return std::isfinite(value) ? format_number(pattern, value) : missing;
}

/// A CSV field in double quotes, inner quotes doubled (RFC 4180).
inline std::string csv_quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

inline std::string join(const std::vector<std::string>& parts, const char* separator) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? separator : "") + parts[i];
  return out;
}

}  // namespace railjoint
