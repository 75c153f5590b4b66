// railjoint.solve_contact(gap_m, ...): the boundary-element normal-contact
// solver (models/normal_contact_solver.h) on a NumPy gap field, with the GIL
// released; the pressure comes back as a NumPy array of the gap's shape.

#include <optional>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "models/half_space_influence.h"
#include "models/normal_contact_solver.h"
#include "support/input_error.h"

namespace py = pybind11;

namespace railjoint::python {

namespace {

using Mask = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>;

py::dict solve_contact(const Eigen::ArrayXXd& gap_m, double cell_x_m, double cell_y_m, double load_N,
                       std::optional<double> yield_pressure_Pa, std::optional<Mask> no_surface,
                       double youngs_modulus_Pa, double poisson_ratio) {
  NormalContactProblem problem;
  problem.gap_m = gap_m;
  if (no_surface) problem.no_surface = *no_surface;
  problem.normal_force_N = load_N;
  problem.yield_pressure_Pa = yield_pressure_Pa;
  problem.keys = {"load_N", "yield_pressure_Pa", "cell_x_m", "gap_m"};
  NormalContactSolution s;
  {
    py::gil_scoped_release release;
    const double e_star = combined_modulus_Pa(youngs_modulus_Pa, poisson_ratio, youngs_modulus_Pa, poisson_ratio);
    try {
      s = solve_normal_contact(problem, cell_x_m, cell_y_m, e_star);
    } catch (const InputError& error) {
      throw error.in_file("solve_contact");  // "solve_contact: key 'load_N': ..."
    }
  }
  py::dict out;
  out["pressure_Pa"] = py::cast(s.pressure_Pa);
  out["approach_m"] = s.approach_m;
  out["carried_force_N"] = s.carried_force_N;
  out["contact_area_m2"] = s.contact_area_m2;
  out["plastic_area_m2"] = s.plastic_area_m2;
  out["max_pressure_Pa"] = s.max_pressure_Pa;
  out["iterations"] = s.iterations;
  out["converged"] = s.converged;
  return out;
}

}  // namespace

void bind_contact(py::module_& m) {
  m.def("solve_contact", &solve_contact, py::arg("gap_m"), py::arg("cell_x_m"), py::arg("cell_y_m"),
        py::arg("load_N"), py::kw_only(), py::arg("yield_pressure_Pa") = py::none(), py::arg("no_surface") = py::none(),
        py::arg("youngs_modulus_Pa") = 210e9, py::arg("poisson_ratio") = 0.3, R"doc(
Frictionless normal contact of two elastic half-spaces of the same steel
(E, nu), on a regular grid (boundary elements; Polonsky and Keer's conjugate
gradient, the convolution by FFT).

gap_m: the undeformed gap [m], a 2-D array, axis 0 along x (cell size
cell_x_m [m]), axis 1 along y (cell_y_m [m]). load_N: the total load [N].
yield_pressure_Pa: a cap on the pressure (elastic-perfectly plastic
interface); None: elastic. no_surface: a boolean array of the gap's shape,
True where there is no surface (no pressure there).

Returns a dict: pressure_Pa (an array of the gap's shape), approach_m,
carried_force_N, contact_area_m2, plastic_area_m2, max_pressure_Pa,
iterations, converged. A patch reaching the grid's border, a cap the grid
cannot carry the load at, or a patch under 8 cells across raises ValueError.
)doc");
}

}  // namespace railjoint::python
