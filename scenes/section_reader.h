#pragma once
// Typed, range-checked reading of one [section] of a scene file. Every key
// of the section that is read is remembered, so finish() can reject keys
// nobody asked for (a typo must never fall back silently to a default) and
// name the keys that were asked for, closest first; and, when asked, every
// key read is recorded with the value used, for the reports to echo. A sweep
// reads a scene per case, so a key read without recording allocates nothing
// (a message is built only when thrown): key names are held as views, and
// must outlive the reader (literals, the key tables of sim/).

#include <toml++/toml.h>

#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scenes/resolved_keys.h"
#include "sim/setting_ranges.h"

namespace railjoint {

/// Closed or open interval for a number, printed in error messages with
/// its unit ("m", "rad", ...; empty for a pure number).
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;
  std::string_view unit = {};

  static Range closed(double a, double b, std::string_view unit = {}) { return {a, b, false, false, unit}; }
  static Range open_closed(double a, double b, std::string_view unit = {}) { return {a, b, true, false, unit}; }
  /// A setting's range as sim/ writes it once (sim/setting_ranges.h).
  static Range of(const SettingRange& r) { return {r.lo, r.hi, r.lo_open, r.hi_open, r.unit}; }

  bool contains(double x) const;
  std::string describe() const;
};

class SectionReader {
 public:
  /// `table` may be null (section absent): every key then takes its default.
  /// `record_keys`: keep every key read with its value, for take_resolved()
  /// (a sweep's cases skip it: docs/benchmarks.md).
  SectionReader(std::string file, std::string section, const toml::table* table, bool record_keys = false);

  bool has(std::string_view key) const;
  /// Whether the scene has the section at all.
  bool present() const { return table_ != nullptr; }
  /// The keys the section gives, read or not, by name.
  std::vector<std::string> given_keys() const;

  double number(std::string_view key, double fallback, const Range& range);
  /// A number that may be left out (the setting then stays empty, and
  /// nothing is recorded); finish() names the key to a typo either way.
  std::optional<double> optional_number(std::string_view key, const Range& range);
  /// A number given in the file in degrees, returned in radians; the range is in degrees.
  double degrees_as_radians(std::string_view key, double fallback_rad, const Range& range_deg);
  long long integer(std::string_view key, long long fallback, long long lo, long long hi);
  bool boolean(std::string_view key, bool fallback);
  /// One of `allowed`, or (when `file_suffix` is given) a file name ending in it.
  std::string choice(std::string_view key, std::string_view fallback, std::span<const std::string_view> allowed,
                     std::string_view file_suffix = {});
  std::string choice(std::string_view key, std::string_view fallback, std::initializer_list<std::string_view> allowed,
                     std::string_view file_suffix = {}) {
    return choice(key, fallback, std::span(allowed.begin(), allowed.size()), file_suffix);
  }
  /// A text (a file name); `fallback` when absent.
  std::string text(std::string_view key, const std::string& fallback);
  /// A number in `range`, or one of `words` (a key whose value may be a
  /// quantity or a named source of it); the word when a word was given,
  /// else empty and `number` set (`fallback` when absent).
  std::string number_or_word(std::string_view key, double fallback, const Range& range,
                             const std::vector<std::string>& words, double& number);

  /// Keys the section takes under another value of its switch, not read
  /// here (switched_keys.h): finish() names them to a typo too. Held as
  /// views, as every key read: names that outlive the reader.
  void expect(std::span<const std::string_view> keys);

  /// Throws InputError for any key in the section that was not read, naming
  /// the keys it takes, closest first.
  void finish() const;

  /// Every key read, with the value used (the default when absent), in the
  /// order read; moved out, for the Scene to keep.
  ResolvedSection take_resolved() { return {section_, std::move(resolved_)}; }

  std::string qualified(std::string_view key) const { return section_ + "." + std::string(key); }
  const std::string& file() const { return file_; }

 private:
  /// The key's node, or null; a key found is remembered for finish().
  const toml::node* lookup(std::string_view key);
  void record(std::string_view key, SceneValue value, bool given);

  std::string file_;
  std::string section_;
  const toml::table* table_;
  std::vector<const toml::node*> read_;  ///< the nodes of the keys read
  std::vector<std::string_view> asked_;  ///< every key looked up, present or not, for finish()'s message
  bool record_keys_;
  std::vector<ResolvedKey> resolved_;
};

}  // namespace railjoint
