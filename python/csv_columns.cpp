#include "csv_columns.h"

#include <charconv>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <pybind11/numpy.h>

namespace py = pybind11;

namespace railjoint::python {

namespace {

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

py::dict csv_columns(const std::string& csv_text) {
  std::string_view text(csv_text);
  const std::size_t header_end = text.find('\n');
  const std::vector<std::string_view> names = split(text.substr(0, header_end));
  std::vector<std::vector<double>> columns(names.size());
  std::vector<bool> has_value(names.size(), false);
  std::size_t start = header_end == std::string_view::npos ? text.size() : header_end + 1;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::vector<std::string_view> cells = split(text.substr(start, end - start));
    if (cells.size() != names.size()) throw std::runtime_error("railjoint: a CSV row with another number of cells");
    for (std::size_t c = 0; c < cells.size(); ++c) {
      columns[c].push_back(number(cells[c]));
      has_value[c] = has_value[c] || !cells[c].empty();
    }
    start = end + 1;
  }
  py::dict out;
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (!has_value[c] && !columns[c].empty()) {
      out[py::str(std::string(names[c]))] = py::none();
      continue;
    }
    py::array_t<double> array(static_cast<py::ssize_t>(columns[c].size()));
    std::copy(columns[c].begin(), columns[c].end(), array.mutable_data());
    array.attr("flags").attr("writeable") = false;
    out[py::str(std::string(names[c]))] = array;
  }
  return out;
}

}  // namespace railjoint::python
