#pragma once
// The columns of a table one of the CLI's CSV writers writes, for the Python
// module: every digit of a double (so the columns read back exactly) and no
// sign on zero, as the CLI's files (support/atomic_file.h) write it.

#include <ostream>

#include "csv_columns.h"
#include "support/no_negative_zero.h"

namespace railjoint::python {

/// The columns of the CSV `write(stream)` writes (csv_columns.h), read as
/// it is written; `rows_hint` reserves them (0: unknown). A KeyboardInterrupt
/// while it writes stops the writer and is raised.
template <class Write>
pybind11::dict csv_columns_of(Write write, std::size_t rows_hint) {
  CsvColumnsBuffer buffer(rows_hint);
  std::ostream out(&buffer);
  out.precision(kExactDigits);
  out.imbue(without_negative_zero(out.getloc()));
  out.exceptions(std::ios::badbit);  // the buffer's exception (Ctrl-C, a bad cell) leaves the writer
  write(out);
  out.flush();
  return buffer.columns();
}

/// The same, read on first use and kept in `cache` (a result's trajectory:
/// formatting it costs more than the call that made it, so a caller that
/// never looks pays nothing).
template <class Write>
pybind11::object cached_csv_columns(pybind11::object& cache, Write write, std::size_t rows_hint) {
  if (!cache) cache = csv_columns_of(write, rows_hint);
  return cache;
}

}  // namespace railjoint::python
