#pragma once
// The parts of the Python module, each adding its classes and functions to
// it (railjoint_module.cpp calls them in this order: a function's signature
// names the classes added before it).

#include <pybind11/pybind11.h>

namespace railjoint::python {

void bind_scene(pybind11::module_& m);     ///< Scene, load_scene
void bind_analytic(pybind11::module_& m);  ///< Prediction, analytic
void bind_simulate(pybind11::module_& m);  ///< Simulation, simulate
void bind_pressure(pybind11::module_& m);  ///< Pressure, pressure
void bind_sweep(pybind11::module_& m);     ///< sweep
void bind_contact(pybind11::module_& m);   ///< solve_contact

}  // namespace railjoint::python
