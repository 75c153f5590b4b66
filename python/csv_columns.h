#pragma once
// A CSV table as the CLI writes it (--csv) turned into columns: a dict from
// each header name to a NumPy float64 array, an empty cell as NaN; a column
// with no value in any row (not applicable to this run: the thesis's
// linearised path of the general model) is None, as the JSON's null. The
// module has the CLI's writers write the CSV text (with every digit of a
// double) and reads it here, so the columns are the CLI's, in its order.

#include <string>

#include <pybind11/pybind11.h>

namespace railjoint::python {

/// Throws std::runtime_error for a cell that is not a number (a bug: the
/// writers it reads write numbers only).
pybind11::dict csv_columns(const std::string& csv_text);

/// Significant digits that write a double so it reads back unchanged.
inline constexpr int kExactDigits = 17;

}  // namespace railjoint::python
