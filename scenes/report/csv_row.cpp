#include "scenes/report/csv_row.h"

#include <charconv>
#include <cmath>

#include "support/no_negative_zero.h"

namespace railjoint {

void CsvRow::separator() {
  if (cells_++ > 0) text_.push_back(',');
}

void CsvRow::number(double value) {
  separator();
  if (!std::isfinite(value)) return;
  value = without_sign_on_zero(value);  // no "-0" (support/no_negative_zero.h)
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  text_.append(buffer, result.ptr);
}

void CsvRow::number(double value, int significant) {
  separator();
  if (!std::isfinite(value)) return;
  if (value == 0.0) value = 0.0;
  char buffer[48];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, significant);
  text_.append(buffer, result.ptr);
}

void CsvRow::append(const CsvRow& other) {
  if (other.cells_ == 0) return;
  if (cells_ > 0) text_.push_back(',');
  text_.append(other.text_);
  cells_ += other.cells_;
}

void CsvRow::integer(long long value) {
  separator();
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  text_.append(buffer, result.ptr);
}

void CsvRow::text(std::string_view value) {
  separator();
  if (value.find_first_of(",\"\n\r") == std::string_view::npos) {
    text_.append(value);
    return;
  }
  text_.push_back('"');
  for (char c : value) {
    if (c == '\n' || c == '\r') c = ' ';  // a row is one line: resuming reads it line by line
    if (c == '"') text_.push_back('"');
    text_.push_back(c);
  }
  text_.push_back('"');
}

void CsvRow::empty(std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) separator();
}

void CsvRow::value(const SceneValue& value) {
  if (const bool* b = std::get_if<bool>(&value)) {
    separator();
    text_.append(*b ? "true" : "false");
  } else if (const long long* i = std::get_if<long long>(&value)) {
    integer(*i);
  } else if (const double* d = std::get_if<double>(&value)) {
    number(*d);
  } else {
    text(std::get<std::string>(value));
  }
}

void CsvRow::end_line() {
  text_.push_back('\n');
  cells_ = 0;
}

void CsvRow::truncate(std::size_t size_in_chars, std::size_t cells) {
  text_.resize(size_in_chars);
  cells_ = cells;
}

}  // namespace railjoint
