#include "scene_values.h"

#include <charconv>
#include <cmath>
#include <variant>

#include "support/input_error.h"

namespace py = pybind11;

namespace railjoint::python {

namespace {

using ScalarValue = std::variant<bool, long long, double, std::string>;

// A value of a type no scene key takes: a TypeError naming the key.
[[noreturn]] void refuse_type(const std::string& file, const std::string& key, const std::string& what) {
  throw py::type_error(InputError(file, key, what).what());
}

// bool before int (True is an int in Python). A NumPy scalar or array
// (anything with dtype, shape and item()) holding one value is that value as
// Python holds it (item(): a float64 stays a float, an int64 an int, a
// bool_ a bool): through __index__ or __int__ a float array would lose its
// fraction (0.03 read as 0). Other numbers through __index__ (integral
// only), then __float__, as Python's own operator.index() and float().
ScalarValue scalar(const py::handle& value, const std::string& file, const std::string& key, bool unwrapped = false) {
  if (PyBool_Check(value.ptr())) return value.cast<bool>();
  if (PyLong_Check(value.ptr())) {
    try {
      return value.cast<long long>();
    } catch (const py::cast_error&) {
      throw InputError(file, key, "an integer of more than 64 bits, got " + std::string(py::str(value)));
    }
  }
  if (PyFloat_Check(value.ptr())) return value.cast<double>();
  if (PyUnicode_Check(value.ptr())) return value.cast<std::string>();
  if (!unwrapped && py::hasattr(value, "dtype") && py::hasattr(value, "shape") && py::hasattr(value, "item")) {
    long long count = 1;
    for (const py::handle& extent : value.attr("shape")) count *= extent.cast<long long>();
    if (count != 1) {
      refuse_type(file, key, "takes one value, got an array of shape " + std::string(py::str(value.attr("shape"))) +
                                 " (index it, e.g. a[0], or make it an axis of a sweep)");
    }
    return scalar(value.attr("item")(), file, key, true);
  }
  const std::string type = py::str(value.get_type().attr("__name__"));
  if (py::hasattr(value, "__index__")) {
    const py::object integer = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
    if (!integer) throw py::error_already_set();
    return scalar(integer, file, key, true);
  }
  if (py::hasattr(value, "__float__")) {
    const py::object real = py::reinterpret_steal<py::object>(PyNumber_Float(value.ptr()));
    if (!real) throw py::error_already_set();
    return real.cast<double>();
  }
  refuse_type(file, key, "takes a number, a text or True/False, got " + type);
}

std::string shortest_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  std::string out(text, end);
  // "30" would read as an integer; a float stays a float (30.0).
  if (out.find_first_of(".eE") == std::string::npos) out += ".0";
  return out;
}

}  // namespace

bool is_boolean(const py::handle& value) {
  return std::holds_alternative<bool>(scalar(value, "", ""));
}

std::string override_text(const py::handle& value, const std::string& file, const std::string& key) {
  const ScalarValue v = scalar(value, file, key);
  // --set reads "key=value" as a line of TOML: a newline in the value would
  // start another assignment (issue 40, item 7).
  if (const std::string* text = std::get_if<std::string>(&v); text && text->find_first_of("\n\r") != std::string::npos) {
    throw InputError(file, key, "takes a one-line value, got \"" + *text + "\": give each key its own entry");
  }
  if (const bool* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
  if (const long long* i = std::get_if<long long>(&v)) return std::to_string(*i);
  if (const double* d = std::get_if<double>(&v)) return shortest_text(*d);
  return std::get<std::string>(v);
}

void insert_scene_value(toml::table& table, const std::string& key, const py::handle& value, const std::string& file,
                        const std::string& dotted_key) {
  std::visit([&](const auto& v) { table.insert_or_assign(key, v); }, scalar(value, file, dotted_key));
}

}  // namespace railjoint::python
