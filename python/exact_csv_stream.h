#pragma once
// A stream the CLI's CSV writers write into for the Python module: every
// digit of a double (so the columns read back exactly) and no sign on zero,
// as the CLI's files (scenes/files/atomic_file.h) write it.

#include <sstream>

#include "csv_columns.h"
#include "scenes/files/no_negative_zero.h"

namespace railjoint::python {

inline std::ostringstream exact_csv_stream() {
  std::ostringstream out;
  out.precision(kExactDigits);
  out.imbue(without_negative_zero(out.getloc()));
  return out;
}

/// The columns of the CSV `write(stream)` writes, read on first use and
/// kept in `cache` (a result's trajectory: formatting it costs more than
/// the call that made it, so a caller that never looks pays nothing).
template <class Write>
pybind11::object cached_csv_columns(pybind11::object& cache, Write write) {
  if (!cache) {
    std::ostringstream csv = exact_csv_stream();
    write(csv);
    cache = csv_columns(csv.str());
  }
  return cache;
}

}  // namespace railjoint::python
