#include "scene_values.h"

#include <charconv>
#include <cmath>
#include <variant>

#include "models/input_error.h"

namespace py = pybind11;

namespace railjoint::python {

namespace {

using ScalarValue = std::variant<bool, long long, double, std::string>;

// bool before int (True is an int in Python); NumPy's scalars through
// __index__ and __float__, as Python's own int() and float() take them.
ScalarValue scalar(const py::handle& value, const std::string& file, const std::string& key) {
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
  if (py::hasattr(value, "__index__")) return py::int_(py::reinterpret_borrow<py::object>(value)).cast<long long>();
  if (py::hasattr(value, "__float__")) return py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
  throw InputError(file, key,
                   "takes a number, a text or True/False, got " + std::string(py::str(value.get_type().attr("__name__"))));
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

std::string override_text(const py::handle& value, const std::string& file, const std::string& key) {
  const ScalarValue v = scalar(value, file, key);
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
