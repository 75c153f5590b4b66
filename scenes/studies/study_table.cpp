#include "scenes/studies/study_table.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "scenes/report/report_text.h"
#include "support/no_negative_zero.h"

namespace railjoint {

namespace {

// A pattern's conversion: the text before its '%', its width, whether it
// pads on the right, and its letter ("%-22s": "", 22, left, 's').
struct Conversion {
  std::string prefix;
  int width = 0;
  bool left = false;
  char letter = 0;
};

Conversion conversion(const std::string& format) {
  Conversion c;
  const std::size_t at = format.find('%');
  if (at == std::string::npos) return c;
  c.prefix = format.substr(0, at);
  std::size_t i = at + 1;
  for (; i < format.size() && std::string_view("-+ 0#").find(format[i]) != std::string_view::npos; ++i) {
    c.left |= format[i] == '-';
  }
  c.width = std::atoi(format.c_str() + i);
  while (i < format.size() && (std::isdigit(static_cast<unsigned char>(format[i])) || format[i] == '.')) ++i;
  if (i < format.size()) c.letter = format[i];
  return c;
}

template <class... Values>
std::string print(const char* pattern, Values... values) {
  char text[1024];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

}  // namespace

StudyTable::StudyTable(std::vector<StudyColumn> columns, StudyTableStyle style)
    : columns_(std::move(columns)), style_(std::move(style)) {}

StudyTable StudyTable::csv_only(const std::string& header) {
  std::vector<StudyColumn> columns;
  for (std::size_t at = 0, comma = 0; comma != std::string::npos; at = comma + 1) {
    comma = header.find(',', at);
    columns.emplace_back(header.substr(at, comma == std::string::npos ? comma : comma - at));
  }
  return StudyTable(std::move(columns));
}

void StudyTable::add(std::vector<StudyCell> cells, StudyRowIn in) {
  if (cells.size() != columns_.size()) {
    throw std::invalid_argument("study table: a row of " + std::to_string(cells.size()) + " cells for " +
                                std::to_string(columns_.size()) + " columns");
  }
  rows_.push_back({std::move(cells), in});
}

bool StudyTable::absent(const StudyCell& cell) const {
  const double* d = std::get_if<double>(&cell.value);
  return std::holds_alternative<std::monostate>(cell.value) || (d && style_.blank_non_finite && !std::isfinite(*d));
}

std::string StudyTable::csv_header() const {
  std::vector<std::string> names;
  for (const StudyColumn& c : columns_) {
    if (!c.csv.empty()) names.push_back(c.csv);
  }
  return join(names, ",");
}

std::string StudyTable::csv_line(std::size_t row) const {
  std::vector<std::string> cells;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (columns_[i].csv.empty()) continue;
    const StudyCell& cell = rows_[row].cells[i];
    std::string& text = cells.emplace_back();
    if (absent(cell)) continue;
    if (const double* d = std::get_if<double>(&cell.value)) {
      text = print("%.10g", without_sign_on_zero(*d));  // as the files' streams write numbers (support/output_file.h)
    } else if (const long long* n = std::get_if<long long>(&cell.value)) {
      text = std::to_string(*n);
    } else if (const bool* b = std::get_if<bool>(&cell.value)) {
      text.push_back(*b ? '1' : '0');
    } else {
      text = std::get<std::string>(cell.value);
      if (columns_[i].quoted) text = csv_quoted(text);
    }
  }
  return join(cells, ",");
}

void StudyTable::write_csv(std::ostream& out) const {
  out << csv_header() << '\n';
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    if (rows_[r].in != StudyRowIn::text) out << csv_line(r) << '\n';
  }
}

std::string StudyTable::text_cell(std::size_t row, std::size_t column) const {
  const StudyColumn& c = columns_[column];
  const StudyCell& cell = rows_[row].cells[column];
  const Conversion form = conversion(c.format);
  std::string text;
  if (cell.shown) {
    text = *cell.shown;
  } else if (absent(cell)) {
    text = style_.missing;
  } else if (const bool* b = std::get_if<bool>(&cell.value)) {
    text = *b ? "yes" : "no";
  } else if (const std::string* s = std::get_if<std::string>(&cell.value)) {
    text = *s;
  } else if (form.letter == 'd' && std::holds_alternative<long long>(cell.value)) {
    return print(c.format.c_str(), static_cast<int>(std::get<long long>(cell.value)));
  } else {
    const long long* n = std::get_if<long long>(&cell.value);
    const double value = (n ? static_cast<double>(*n) : std::get<double>(cell.value)) * c.scale;
    // Without "-0" (no_negative_zero.h), but a fixed-width cell as printf
    // pads it: dropping the sign there would shift the columns after it.
    text = print(c.format.empty() || form.letter == 's' ? "%g" : c.format.c_str(), value);
    if (form.width == 0) text = without_negative_zeros(text);
  }
  return form.letter == 's' ? print(c.format.c_str(), text.c_str()) : text;
}

std::vector<std::string> StudyTable::text_cells(std::size_t row) const {
  std::vector<std::string> cells;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (!columns_[i].text.empty()) cells.push_back(row < rows_.size() ? text_cell(row, i) : columns_[i].text);
  }
  return cells;
}

std::string StudyTable::text_header() const { return "| " + join(text_cells(rows_.size()), " | ") + " |"; }

std::string StudyTable::markdown() const {
  std::string out = text_header() + "\n|";
  for (const StudyColumn& c : columns_) {
    if (c.text.empty()) continue;
    out += !style_.plain_rule && !c.format.empty() && !conversion(c.format).left ? "---:|" : "---|";
  }
  out += '\n';
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    if (rows_[r].in != StudyRowIn::csv) out += "| " + join(text_cells(r), " | ") + " |\n";
  }
  return out;
}

std::string StudyTable::aligned(const std::string& separator, bool header) const {
  std::vector<std::string> headers;
  for (const StudyColumn& c : columns_) {
    if (c.text.empty()) continue;
    const Conversion p = conversion(c.format);
    const std::string name = c.text.find_first_not_of(' ') == std::string::npos ? "" : c.text;
    const std::string fill(static_cast<std::size_t>(std::max(0, p.width - static_cast<int>(name.size()))), ' ');
    headers.push_back(p.prefix + (p.left ? name + fill : fill + name));
  }
  while (!headers.empty() && headers.back().empty()) headers.pop_back();
  std::string out = header ? join(headers, separator.c_str()) + '\n' : "";
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    if (rows_[r].in != StudyRowIn::csv) out += join(text_cells(r), separator.c_str()) + '\n';
  }
  return out;
}

}  // namespace railjoint
