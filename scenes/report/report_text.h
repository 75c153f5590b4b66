#pragma once
// Small text helpers the study reports share: printf-style numbers, CSV
// quoting and joining.

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>
#include <vector>

#include "support/no_negative_zero.h"

namespace railjoint {

/// std::vsnprintf into a string, without negative zeros ("x = -0.0000 mm"
/// for -3e-9 m: support/no_negative_zero.h).
inline std::string vtext_of(const char* format, std::va_list arguments) {
  std::va_list again;
  va_copy(again, arguments);
  const int size = std::vsnprintf(nullptr, 0, format, arguments);
  std::string text(size > 0 ? static_cast<std::size_t>(size) : 0, '\0');
  if (size > 0) std::vsnprintf(text.data(), text.size() + 1, format, again);
  va_end(again);
  return without_negative_zeros(std::move(text));
}

/// std::printf into a string, without negative zeros.
[[gnu::format(printf, 1, 2)]] inline std::string text_of(const char* format, ...) {
  std::va_list arguments;
  va_start(arguments, format);
  std::string text = vtext_of(format, arguments);
  va_end(arguments);
  return text;
}

/// std::printf for a report's text on stdout, without negative zeros.
[[gnu::format(printf, 1, 2)]] inline void print_text(const char* format, ...) {
  std::va_list arguments;
  va_start(arguments, format);
  std::fputs(vtext_of(format, arguments).c_str(), stdout);
  va_end(arguments);
}

/// One number through a printf pattern, e.g. format_number("%.3g mm", x); no negative zero.
inline std::string format_number(const char* pattern, double value) {
  char text[96];
  std::snprintf(text, sizeof text, pattern, value);
  return without_negative_zeros(text);
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
