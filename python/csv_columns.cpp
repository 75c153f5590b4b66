#include "csv_columns.h"

#include <charconv>
#include <limits>
#include <stdexcept>
#include <string_view>

#include <pybind11/numpy.h>

namespace py = pybind11;

namespace railjoint::python {

namespace {

// Room for many rows between reads (a row of a trajectory is ~300 characters).
constexpr std::size_t kBufferBytes = 1 << 16;
// Rows between runs of Python's signal handlers: a few milliseconds of writing.
constexpr std::size_t kSignalCheckRows = 1 << 14;

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return cells;
    start = comma + 1;
  }
}

double number(std::string_view cell) {
  if (cell.empty()) return std::numeric_limits<double>::quiet_NaN();
  double value = 0.0;
  const auto [end, status] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (status != std::errc{} || end != cell.data() + cell.size()) {
    throw std::runtime_error("railjoint: a CSV cell that is not a number: \"" + std::string(cell) + "\"");
  }
  return value;
}

}  // namespace

CsvColumnsBuffer::CsvColumnsBuffer(std::size_t rows_hint) : buffer_(kBufferBytes), rows_hint_(rows_hint) {
  setp(buffer_.data(), buffer_.data() + buffer_.size());
}

CsvColumnsBuffer::int_type CsvColumnsBuffer::overflow(int_type c) {
  read_lines();
  if (pptr() == epptr()) {  // one line longer than the buffer: make room for it
    const std::size_t used = buffer_.size();
    buffer_.resize(2 * used);
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    pbump(static_cast<int>(used));
  }
  if (!traits_type::eq_int_type(c, traits_type::eof())) {
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
  }
  return traits_type::not_eof(c);
}

int CsvColumnsBuffer::sync() {
  read_lines();
  return 0;
}

// Reads the complete lines written so far and moves the unfinished one to the front.
void CsvColumnsBuffer::read_lines() {
  const std::string_view text(pbase(), static_cast<std::size_t>(pptr() - pbase()));
  std::size_t start = 0;
  for (std::size_t end = text.find('\n'); end != std::string_view::npos; end = text.find('\n', start)) {
    read_line(text.substr(start, end - start));
    start = end + 1;
  }
  const std::size_t rest = text.size() - start;
  std::copy(text.data() + start, text.data() + text.size(), buffer_.data());
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  pbump(static_cast<int>(rest));
}

void CsvColumnsBuffer::read_line(std::string_view line) {
  const std::vector<std::string_view> cells = split(line);
  if (!header_read_) {
    header_read_ = true;
    for (const std::string_view name : cells) names_.emplace_back(name);
    columns_.resize(names_.size());
    has_value_.assign(names_.size(), false);
    for (std::vector<double>& column : columns_) column.reserve(rows_hint_);
    return;
  }
  if (cells.size() != names_.size()) throw std::runtime_error("railjoint: a CSV row with another number of cells");
  for (std::size_t c = 0; c < cells.size(); ++c) {
    columns_[c].push_back(number(cells[c]));
    if (!cells[c].empty()) has_value_[c] = true;
  }
  if (++rows_ % kSignalCheckRows == 0 && PyErr_CheckSignals() != 0) throw py::error_already_set();
}

py::dict CsvColumnsBuffer::columns() {
  read_lines();
  if (pptr() != pbase()) read_line(std::string_view(pbase(), static_cast<std::size_t>(pptr() - pbase())));
  py::dict out;
  for (std::size_t c = 0; c < names_.size(); ++c) {
    if (!has_value_[c] && !columns_[c].empty()) {
      out[py::str(names_[c])] = py::none();
      continue;
    }
    // The array keeps the column's own buffer: no copy of it.
    auto* column = new std::vector<double>(std::move(columns_[c]));
    const py::capsule owner(column, [](void* p) { delete static_cast<std::vector<double>*>(p); });
    py::array_t<double> array(static_cast<py::ssize_t>(column->size()), column->data(), owner);
    array.attr("flags").attr("writeable") = false;
    out[py::str(names_[c])] = array;
  }
  return out;
}

}  // namespace railjoint::python
