#pragma once
// How a result's fields become Python values, by the JSON reports' rule
// (scenes/report/json_values.h): what is missing (not finite, not measured)
// is None, never NaN or 0; a point is an (x, y, z) tuple in metres.

#include <Eigen/Core>
#include <pybind11/pybind11.h>

namespace railjoint::python {

pybind11::object finite_or_none(double value);
pybind11::object measured_or_none(bool measured, double value);
/// (x, y, z), or None when a component is not finite (a point never found).
pybind11::object point_or_none(const Eigen::Vector3d& point);

}  // namespace railjoint::python
