#pragma once
// Numbers written without a sign on zero: a quantity computed as -0.0 (a
// penetration that never happened, the rate of a constant pressure) is 0 to
// a reader, and "-0" in a CSV or JSON reads as a sign that means something.

#include <cctype>
#include <locale>
#include <string>

namespace railjoint {

/// `value`, but 0.0 for -0.0: the one place a zero loses its sign, for every
/// writer of numbers (the stream facet below, CSV rows, tables, Python's values).
constexpr double without_sign_on_zero(double value) { return value == 0.0 ? 0.0 : value; }

/// Writes -0.0 as 0 and every other number as std::num_put does.
class NoNegativeZero : public std::num_put<char> {
 protected:
  iter_type do_put(iter_type out, std::ios_base& stream, char_type fill, double value) const override {
    return std::num_put<char>::do_put(out, stream, fill, without_sign_on_zero(value));
  }
  iter_type do_put(iter_type out, std::ios_base& stream, char_type fill, long double value) const override {
    return std::num_put<char>::do_put(out, stream, fill, value == 0.0L ? 0.0L : value);
  }
};

/// `base` with NoNegativeZero for writing numbers (imbue it into a stream).
inline std::locale without_negative_zero(const std::locale& base) { return std::locale(base, new NoNegativeZero); }

/// Formatted text (a report's line) with the sign dropped from every number
/// it shows as zero: "-0", "-0.0000", "-0.0000e+00". A value of -3e-9 printed
/// to four decimals is 0 to a reader too, which no stream facet can see.
inline std::string without_negative_zeros(std::string text) {
  const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '_'; };
  for (std::size_t at = text.find('-'); at != std::string::npos; at = text.find('-', at + 1)) {
    if (at > 0 && word(text[at - 1])) continue;  // a hyphen in a word, an exponent's sign
    std::size_t end = at + 1;
    bool zeros = false;
    for (; end < text.size() && (text[end] == '0' || text[end] == '.'); ++end) zeros = zeros || text[end] == '0';
    if (!zeros || (end < text.size() && digit(text[end]))) continue;
    if (end < text.size() && (text[end] == 'e' || text[end] == 'E')) {
      std::size_t exponent = end + 1;
      if (exponent < text.size() && (text[exponent] == '+' || text[exponent] == '-')) ++exponent;
      const std::size_t first = exponent;
      while (exponent < text.size() && digit(text[exponent])) ++exponent;
      if (exponent > first) end = exponent;
    }
    if (end < text.size() && word(text[end])) continue;
    text.erase(at, 1);
  }
  return text;
}

}  // namespace railjoint
