// railjoint.Pressure and railjoint.pressure(scene): the local model (thesis
// ch. 5-6), as `railjoint pressure` runs it, with the GIL released.

#include <pybind11/stl.h>

#include "bindings.h"
#include "cli_help.h"
#include "column_arrays.h"
#include "frozen_result.h"
#include "json_dict.h"
#include "python_scene.h"
#include "scenes/local_model_run.h"
#include "scenes/report/pressure_report.h"

namespace py = pybind11;

namespace railjoint::python {

namespace {

struct PressureRun {
  std::shared_ptr<const Scene> scene;
  LocalModelRun result;
  py::object traversal;  ///< the columns, made on first use
  py::object frozen;     ///< an unpickled run's state (frozen_result.h); null otherwise
};

std::shared_ptr<PressureRun> pressure(const PythonScene& scene) {
  auto run = std::make_shared<PressureRun>();
  run->scene = scene.checked(SceneCheck::keys_only);  // as `pressure`: the local model checks its own combinations
  py::gil_scoped_release release;
  run->result = naming_scene_file(*run->scene, [&] { return run_local_model(*run->scene); });
  return run;
}

py::object traversal(PressureRun& run) {
  return columns_on_first_use(run.frozen, run.traversal, [&] { return column_arrays(pressure_table(run.result)); });
}

}  // namespace

void bind_pressure(py::module_& m) {
  py::class_<PressureRun, std::shared_ptr<PressureRun>> c(m, "Pressure", R"doc(
The local model's run (thesis ch. 5-6): a contact patch crossing the
end-post gap, its uniform pressure N / A over the active area, the rate
dP/dt, the maxima. SI units, each in the field's name.
)doc");
  const auto summary = [](const PressureRun& r) -> const PressureSummary& { return r.result.summary; };
  add_result_property(c, "initial_area_m2", [summary](const PressureRun& r) { return summary(r).initial_area_m2; },
                      "A0, the patch's area before the gap [m^2]");
  add_result_property(c, "p0_Pa", [summary](const PressureRun& r) { return summary(r).p0_Pa; },
                      "P0 = N / A0, the pressure before the gap [Pa]");
  add_result_property(c, "g_long_m", [summary](const PressureRun& r) { return summary(r).g_long_m; },
                      "The gap's length along the track, g / sin(theta) [m]");
  add_result_property(
      c, "max_pressure_Pa", [summary](const PressureRun& r) { return summary(r).at_max_pressure.pressure_Pa; },
      "Largest uniform pressure over the crossing [Pa]");
  add_result_property(
      c, "max_relative_pressure", [summary](const PressureRun& r) { return summary(r).max_relative_pressure(); },
      "Largest pressure over P0 [-]");
  add_result_property(
      c, "x_at_max_pressure_m", [summary](const PressureRun& r) { return summary(r).at_max_pressure.x_front_m; },
      "Position of the patch's front at the largest pressure [m]");
  add_result_property(
      c, "max_rate_Pa_per_s",
      [summary](const PressureRun& r) { return summary(r).max_abs_rate_Pa_per_s(r.result.inputs.speed_m_per_s); },
      "Largest |dP/dt| over the crossing [Pa/s]");
  c.def_property_readonly("traversal", &traversal, R"doc(
The traversal, one entry per position of the patch: a dict from each column of
`railjoint pressure --csv` to a read-only float64 NumPy array of the computed
doubles (no text between; -0.0 as 0.0, as the CSV writes it): x_front_m, t_s, reduction_area_m2, active_area_m2, relative_active_area,
pressure_Pa, relative_pressure, rate_Pa_per_m, rate_Pa_per_s, and for an
ellipse hertz_peak_pressure_Pa, hertz_force_incoming_N, hertz_force_outgoing_N.
Made on first use, then kept.
)doc");
  c.def(
      "traversal_frame",
      [](const py::object& self) {
        return columns_frame(self.attr("traversal"), "railjoint.Pressure.traversal_frame()", "Pressure.traversal");
      },
      "The traversal as a pandas.DataFrame: the same columns in --csv's order, float64 (pandas imported on first "
      "use; ImportError without it)");
  c.def("as_dict", [](const PressureRun& r) -> py::object {
          return r.frozen ? frozen_report(r.frozen) : py::object(report_dict(pressure_to_json(*r.scene, r.result)));
        },
        "The run as `railjoint pressure SCENE --json` prints it, parsed (dict)");
  c.def("__repr__", [](const py::object& self) {
    return "railjoint.Pressure(max_pressure_Pa=" + std::string(py::repr(self.attr("max_pressure_Pa"))) + ")";
  });
  // A copy holds the same run; pickle carries its values and columns (frozen_result.h).
  add_run_copy(c, &PressureRun::traversal);
  add_frozen_pickle(c, "traversal");

  static const std::string doc = command_doc(R"doc(The local model (thesis ch. 5-6): the uniform contact pressure [Pa] of the
scene's patch crossing the end-post gap, its rate dP/dt [Pa/s], the maxima.
The GIL is released while it runs.

scene : a Scene; its [contact_patch], joint.theta_deg, joint.gap,
        wheel.speed and wheel.radius are read
Raises ValueError, with the CLI's message, for a patch or gap the model
cannot describe. Pressure.as_dict() equals `railjoint pressure SCENE --json`;
Pressure.traversal holds the columns of --csv.
)doc", "pressure");
  m.def("pressure", &pressure, py::arg("scene"), doc.c_str());
}

}  // namespace railjoint::python
