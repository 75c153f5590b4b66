#pragma once
// Typed, range-checked reading of one [section] of a scene file. Every key
// that is read is remembered, so finish() can reject keys nobody asked for
// (a typo must never fall back silently to a default).

#include <limits>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace railjoint {

/// Closed or open interval for a number, printed in error messages.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range open_closed(double a, double b) { return {a, b, true, false}; }

  bool contains(double x) const;
  std::string describe() const;
};

class SectionReader {
 public:
  /// `table` may be null (section absent): every key then takes its default.
  SectionReader(std::string file, std::string section, const toml::table* table);

  bool has(const std::string& key) const;

  double number(const std::string& key, double fallback, const Range& range);
  /// A number given in the file in degrees, returned in radians; the range is in degrees.
  double degrees_as_radians(const std::string& key, double fallback_rad, const Range& range_deg);
  long long integer(const std::string& key, long long fallback, long long lo, long long hi);
  bool boolean(const std::string& key, bool fallback);
  std::string choice(const std::string& key, const std::string& fallback, const std::vector<std::string>& allowed);

  /// Throws InputError for any key in the section that was not read.
  void finish() const;

  std::string qualified(const std::string& key) const { return section_ + "." + key; }
  const std::string& file() const { return file_; }

 private:
  const toml::node* lookup(const std::string& key);

  std::string file_;
  std::string section_;
  const toml::table* table_;
  std::set<std::string> read_;
};

}  // namespace railjoint
