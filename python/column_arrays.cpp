#include "column_arrays.h"

#include <limits>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "support/no_negative_zero.h"

namespace py = pybind11;

namespace railjoint::python {

py::dict column_arrays(ColumnTable&& table) {
  py::dict out;
  for (TableColumn& column : table.columns()) {
    bool has_value = false;
    for (double& value : column.values) {
      value = without_sign_on_zero(value);  // no "-0" (support/no_negative_zero.h)
      has_value = has_value || value == value;
    }
    if (!has_value && !column.values.empty()) {
      out[py::str(column.name)] = py::none();
      continue;
    }
    // The array keeps the column's own buffer: no copy of it, unless a
    // vector grown by push_back holds much more than its values.
    if (column.values.capacity() - column.values.size() > column.values.size() / 8) column.values.shrink_to_fit();
    auto* values = new std::vector<double>(std::move(column.values));
    const py::capsule owner(values, [](void* p) { delete static_cast<std::vector<double>*>(p); });
    py::array_t<double> array(static_cast<py::ssize_t>(values->size()), values->data(), owner);
    array.attr("flags").attr("writeable") = false;
    out[py::str(column.name)] = array;
  }
  return out;
}

py::object columns_frame(const py::object& columns, const char* call, const char* arrays) {
  py::module_ pandas;
  try {
    pandas = py::module_::import("pandas");
  } catch (const py::error_already_set& error) {
    if (!error.matches(PyExc_ImportError)) throw;
    throw py::import_error(std::string(call) + " needs pandas, which this Python cannot import (Debian: apt-get "
                           "install python3-pandas); " + arrays + " holds the same columns as NumPy arrays");
  }
  const py::dict dict = columns;
  py::ssize_t rows = 0;
  for (const auto& [name, column] : dict) {
    if (!column.is_none()) rows = py::len(column);
  }
  const py::module_ numpy = py::module_::import("numpy");
  py::dict frame_columns;
  for (const auto& [name, column] : dict) {
    frame_columns[name] = column.is_none()
                              ? numpy.attr("full")(rows, std::numeric_limits<double>::quiet_NaN())
                              : py::reinterpret_borrow<py::object>(column);
  }
  return pandas.attr("DataFrame")(frame_columns);
}

}  // namespace railjoint::python
