#include "result_values.h"

#include <cmath>

namespace py = pybind11;

namespace railjoint::python {

py::object finite_or_none(double value) { return std::isfinite(value) ? py::object(py::float_(value)) : py::none(); }

py::object measured_or_none(bool measured, double value) { return measured ? py::object(py::float_(value)) : py::none(); }

py::object point_or_none(const Eigen::Vector3d& point) {
  if (!point.allFinite()) return py::none();
  return py::make_tuple(point.x(), point.y(), point.z());
}

}  // namespace railjoint::python
