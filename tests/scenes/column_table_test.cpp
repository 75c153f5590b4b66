// A result's table written as CSV (scenes/report/column_table.h): the
// header, then each row's numbers as the output file's stream formats them,
// NaN an empty cell. Expected lines written out by hand.

#include "scenes/report/column_table.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/no_negative_zero.h"

namespace railjoint {
namespace {

// As support/atomic_file.cpp sets up an output file: 12 significant digits, no "-0".
std::string written(const ColumnTable& table) {
  std::ostringstream out;
  out.precision(12);
  out.imbue(without_negative_zero(out.getloc()));
  write_csv(table, out);
  return out.str();
}

TEST(ColumnTable, WritesTheHeaderThenARowPerLineWithNaNAsAnEmptyCell) {
  ColumnTable table(3);
  const double t_s[] = {0.5, -0.0, 1.0 / 3.0};
  table.add_column("t_s", [&](std::size_t k) { return t_s[k]; });
  std::vector<double>& y = table.add_column("y_m");  // empty but where filled
  y[1] = 2.0;
  table.add_column("contacts", [](std::size_t k) { return static_cast<double>(k + 1); });
  EXPECT_EQ(written(table), "t_s,y_m,contacts\n0.5,,1\n0,2,2\n0.333333333333,,3\n");
}

TEST(ColumnTable, TakesAColumnOfValuesInItsPlace) {
  ColumnTable table(2);
  table.add_column("t_s", std::vector<double>{-1e-3, 2.5e-17});
  table.add_column("x_m", [](std::size_t k) { return 0.25 * static_cast<double>(k); });
  EXPECT_EQ(written(table), "t_s,x_m\n-0.001,0\n2.5e-17,0.25\n");
}

TEST(ColumnTable, AnEmptyTableIsItsHeader) {
  ColumnTable table(0);
  table.add_column("x_m");
  table.add_column("z_m");
  EXPECT_EQ(written(table), "x_m,z_m\n");
}

TEST(ColumnTable, ANewColumnIsEmptyCellsOfTheTablesRows) {
  ColumnTable table(4);
  const std::vector<double>& column = table.add_column("rail_z_m");
  ASSERT_EQ(column.size(), 4u);
  for (double value : column) EXPECT_TRUE(std::isnan(value));
  EXPECT_EQ(table.columns().front().name, "rail_z_m");
}

}  // namespace
}  // namespace railjoint
