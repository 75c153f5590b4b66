#include "json_dict.h"

#include "scenes/report/json_values.h"

namespace py = pybind11;

namespace railjoint::python {

py::dict report_dict(const nlohmann::json& report) {
  return py::module_::import("json").attr("loads")(report_text(report));
}

}  // namespace railjoint::python
