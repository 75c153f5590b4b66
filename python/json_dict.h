#pragma once
// A JSON report as a Python dict: the text the CLI prints with --json
// (report_text, scenes/report/json_values.h) read by Python's json module,
// so as_dict() equals json.loads of the CLI's output, value for value.

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace railjoint::python {

pybind11::dict report_dict(const nlohmann::json& report);

}  // namespace railjoint::python
