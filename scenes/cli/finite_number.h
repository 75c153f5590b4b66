#pragma once
// The check of a number flag: finite and within [lo, hi]. CLI11's Range and
// NonNegativeNumber compare with < and >, which nan passes, and admit inf
// and 1e308: every number flag of every command takes this one instead.

#include <charconv>
#include <cmath>
#include <sstream>
#include <string>
#include <system_error>

#include <CLI/CLI.hpp>

namespace railjoint::cli {

inline CLI::Validator finite_in(double lo, double hi, const std::string& unit) {
  std::ostringstream range;
  range << "[" << lo << ", " << hi << "]" << (unit.empty() ? "" : " " + unit);
  return CLI::Validator(
      [lo, hi, allowed = range.str()](std::string& text) -> std::string {
        // from_chars: a decimal number only (strtod also reads hexadecimal,
        // so "0x10" was 16 mm), and no locale; a leading '+' as strtod took it.
        double value = 0.0;
        const char* const first = text.data() + (text.size() > 1 && text[0] == '+' ? 1 : 0);
        const char* const last = text.data() + text.size();
        const auto [end, error] = std::from_chars(first, last, value);
        const bool out_of_range = error == std::errc::result_out_of_range && end == last;  // 1e400, 1e-400
        if (text.empty() || (error != std::errc() && !out_of_range) || end != last) {
          return "\"" + text + "\" is not a number";
        }
        if (out_of_range || !std::isfinite(value) || value < lo || value > hi) {
          return "must be a finite number in " + allowed + ", got " + text;
        }
        return {};
      },
      "FINITE in " + range.str());
}

}  // namespace railjoint::cli
