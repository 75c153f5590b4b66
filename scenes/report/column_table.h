#pragma once
// One result's table of numbers, built once from the result, column by
// column: the CLI's CSV writes it (write_csv) and the Python module hands
// its columns to NumPy as they are, with no text between. A column's name
// carries its unit, as the CSV header does; NaN is an empty cell (nothing
// to report in that row: contact_y_m in flight, the linearised path where
// the thesis's jump has no real value). Columns: scenes/report/outputs.md.

#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace railjoint {

struct TableColumn {
  std::string name;            ///< with its unit: "t_s", "contact_force_z_N"
  std::vector<double> values;  ///< one per row; NaN: an empty cell
};

class ColumnTable {
 public:
  explicit ColumnTable(std::size_t rows) : rows_(rows) {}

  /// A new last column of rows() empty cells, for the caller to fill.
  std::vector<double>& add_column(std::string name);
  /// A new last column of these values, one per row (moved in: no copy).
  void add_column(std::string name, std::vector<double> values);
  /// A new last column whose cell in row k is cell(k).
  template <class Cell>
  void add_column(std::string name, Cell cell) {
    std::vector<double>& values = add_column(std::move(name));
    for (std::size_t k = 0; k < rows_; ++k) values[k] = cell(k);
  }

  std::size_t rows() const { return rows_; }
  const std::vector<TableColumn>& columns() const { return columns_; }
  /// The columns to move from (the Python module takes their buffers).
  std::vector<TableColumn>& columns() { return columns_; }

 private:
  std::size_t rows_;
  std::vector<TableColumn> columns_;
};

/// The header line, then a line per row: each number as `out` formats a
/// double (the output file's significant digits, no sign on zero), NaN as
/// an empty cell.
void write_csv(const ColumnTable& table, std::ostream& out);

}  // namespace railjoint
