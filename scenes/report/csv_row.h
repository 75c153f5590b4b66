#pragma once
// One CSV line built cell by cell, cheaply: numbers in their shortest form
// that reads back to the same double (std::to_chars), texts quoted only
// when they must be (RFC 4180). Not applicable or not finite = an empty
// cell, as the JSON outputs write null (y_t of a square joint: no transition
// value, every wheel position is scenario 1).

#include <cstddef>
#include <string>
#include <string_view>

#include "scenes/resolved_keys.h"

namespace railjoint {

class CsvRow {
 public:
  void number(double value);
  /// With `significant` digits (measurements such as wall times, whose last digits are noise).
  void number(double value, int significant);
  void integer(long long value);
  void text(std::string_view value);
  void boolean(bool value) { integer(value ? 1 : 0); }
  void empty(std::size_t count = 1);
  /// A scene value as the sweep file gave it (true/false for booleans).
  void value(const SceneValue& value);
  /// Appends another row's cells after this row's.
  void append(const CsvRow& other);
  /// Ends the line ('\n') and starts the next one in the same buffer.
  void end_line();

  std::size_t cells() const { return cells_; }
  const std::string& str() const { return text_; }
  std::string& str() { return text_; }
  /// Drops the cells after the first `cells` of this line (a model that failed half way).
  void truncate(std::size_t size_in_chars, std::size_t cells);
  std::size_t size() const { return text_.size(); }

 private:
  void separator();
  std::string text_;
  std::size_t cells_ = 0;
};

}  // namespace railjoint
