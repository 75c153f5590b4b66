#pragma once
// The check of a number flag: finite and within [lo, hi]. CLI11's Range and
// NonNegativeNumber compare with < and >, which nan passes, and admit inf
// and 1e308: every number flag of every command takes this one instead.

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

namespace railjoint::cli {

inline CLI::Validator finite_in(double lo, double hi, const std::string& unit) {
  std::ostringstream range;
  range << "[" << lo << ", " << hi << "]" << (unit.empty() ? "" : " " + unit);
  return CLI::Validator(
      [lo, hi, allowed = range.str()](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return "\"" + text + "\" is not a number";
        if (!std::isfinite(value) || value < lo || value > hi) {
          return "must be a finite number in " + allowed + ", got " + text;
        }
        return {};
      },
      "FINITE in " + range.str());
}

}  // namespace railjoint::cli
