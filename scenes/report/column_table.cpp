#include "scenes/report/column_table.h"

#include <cassert>
#include <cmath>
#include <limits>

namespace railjoint {

std::vector<double>& ColumnTable::add_column(std::string name) {
  columns_.push_back({std::move(name), std::vector<double>(rows_, std::numeric_limits<double>::quiet_NaN())});
  return columns_.back().values;
}

void ColumnTable::add_column(std::string name, std::vector<double> values) {
  assert(values.size() == rows_);
  columns_.push_back({std::move(name), std::move(values)});
}

void write_csv(const ColumnTable& table, std::ostream& out) {
  const std::vector<TableColumn>& columns = table.columns();
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c > 0 ? "," : "") << columns[c].name;
  out << '\n';
  for (std::size_t row = 0; row < table.rows(); ++row) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c > 0) out << ',';
      const double value = columns[c].values[row];
      if (!std::isnan(value)) out << value;
    }
    out << '\n';
  }
}

}  // namespace railjoint
