#include "path_argument.h"

namespace py = pybind11;

namespace railjoint::python {

std::string path_argument(const py::handle& value, const char* argument) {
  const py::module_ os = py::module_::import("os");
  py::object fs_path;
  try {
    fs_path = os.attr("fspath")(value);
  } catch (const py::error_already_set& error) {
    if (!error.matches(PyExc_TypeError)) throw;
    throw py::type_error(std::string(argument) + ": takes a path (str, bytes or os.PathLike), got " +
                         std::string(py::str(value.get_type().attr("__name__"))));
  }
  const std::string bytes = os.attr("fsencode")(fs_path).cast<std::string>();
  if (bytes.find('\0') != std::string::npos) {
    throw py::value_error(std::string(argument) + ": a path with a NUL character, " +
                          std::string(py::repr(fs_path)) + ": no file name holds one");
  }
  return bytes;
}

py::str path_text(const std::string& path) {
  return py::module_::import("os").attr("fsdecode")(py::bytes(path));
}

}  // namespace railjoint::python
