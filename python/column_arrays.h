#pragma once
// A result's table (scenes/report/column_table.h) as Python holds it: a dict
// from each column's name to a read-only float64 NumPy array that owns the
// column's own buffer (no text, no copy): exactly the doubles the table
// holds, but -0.0 as 0.0, as every output of the CLI writes zero. A column
// with no value in any row (not applicable to this run: the thesis's
// linearised path of the general model) is None, as the JSON's null; an
// empty cell in a column that has values is NaN.

#include <pybind11/pybind11.h>

#include "scenes/report/column_table.h"

namespace railjoint::python {

/// The table's columns, moved out of it.
pybind11::dict column_arrays(ColumnTable&& table);

/// The same columns as a pandas.DataFrame of float64 columns in the table's
/// order (a None column is all NaN, as pandas reads a column of empty cells).
/// pandas is imported here, on first use; without it, ImportError naming
/// `call` and the arrays that need no pandas.
pybind11::object columns_frame(const pybind11::object& columns, const char* call, const char* arrays);

}  // namespace railjoint::python
