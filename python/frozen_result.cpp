#include "frozen_result.h"

namespace py = pybind11;

namespace railjoint::python {

py::dict frozen_state(const py::object& self, const char* columns_property) {
  const py::module_ builtins = py::module_::import("builtins");
  const py::object cls = py::type::of(self);
  py::dict fields;
  for (const py::handle& name : builtins.attr("dir")(cls)) {
    const std::string text = py::str(name);
    if (text.empty() || text[0] == '_' || (columns_property && text == columns_property)) continue;
    if (py::isinstance(cls.attr(name), builtins.attr("property"))) fields[name] = self.attr(name);
  }
  py::dict state;
  state["fields"] = fields;
  state["as_dict"] = self.attr("as_dict")();
  state["columns"] = columns_property ? py::object(self.attr(columns_property)) : py::object(py::none());
  return state;
}

py::object frozen_field(const py::object& frozen, const char* name) {
  const py::dict fields = frozen["fields"];
  return fields.contains(name) ? py::object(fields[name]) : py::none();
}

py::object frozen_report(const py::object& frozen) {
  return py::module_::import("copy").attr("deepcopy")(frozen["as_dict"]);
}

py::object frozen_columns(const py::object& frozen) { return frozen["columns"]; }

}  // namespace railjoint::python
