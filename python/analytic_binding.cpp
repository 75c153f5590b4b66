// railjoint.Prediction and railjoint.analytic(scene): the kinematic model
// (thesis ch. 3-4), as `railjoint analytic` runs it.

#include <pybind11/stl.h>

#include "bindings.h"
#include "cli_help.h"
#include "column_arrays.h"
#include "frozen_result.h"
#include "interruptible_run.h"
#include "json_dict.h"
#include "prediction_result.h"
#include "python_scene.h"
#include "result_values.h"
#include "scenes/report/prediction_csv.h"
#include "scenes/report/prediction_json.h"

namespace py = pybind11;

namespace railjoint::python {

namespace {

template <class Get>
void field(py::class_<PredictionResult>& c, const char* name, Get get, const char* doc) {
  add_result_property(c, name, [get](const PredictionResult& r) { return get(r.prediction); }, doc);
}

py::object prediction_dict(const PredictionResult& r) {
  if (r.frozen) return frozen_report(r.frozen);
  if (r.json_block) return report_dict(*r.json_block);
  nlohmann::json report = r.scene ? analytic_report_to_json(*r.scene, r.prediction) : prediction_to_json(r.prediction);
  if (r.profile_smoothing) report["profile_smoothing"] = *r.profile_smoothing;
  return report_dict(report);
}

PredictionResult analytic(const PythonScene& scene) {
  const std::shared_ptr<const Scene> checked = scene.checked(SceneCheck::model);
  const ImpactPrediction& prediction = *checked->prediction;
  return {prediction, checked, profile_smoothing_json(checked->joint, checked->wheel, prediction)};
}

// `analytic --csv --before-mm B --after-mm A --samples N`, as columns.
py::dict time_history(const PredictionResult& r, double before_mm, double after_mm, int samples) {
  if (r.frozen) {
    throw std::invalid_argument("time_history() needs the model, which an unpickled Prediction does not carry: "
                                "call railjoint.analytic(scene) in this process");
  }
  if (!r.scene) {
    throw std::invalid_argument("time_history() needs the prediction of analytic(scene): this one is a simulation's");
  }
  if (samples < 2 || samples > 10'000'000) throw InputError(r.scene->file, "samples", "must be in [2, 10000000]");
  // The CLI's --before-mm and --after-mm checks (finite_in(0, 1e5, "mm"),
  // then the rails' reach), naming this function's arguments.
  for (const auto& [argument, travel_mm] : {std::pair{"before_mm", before_mm}, std::pair{"after_mm", after_mm}}) {
    if (!(travel_mm >= 0.0 && travel_mm <= 1e5)) {
      std::ostringstream message;
      message << "must be a finite number in [0, 100000] mm, got " << travel_mm;
      throw InputError("time_history", argument, message.str());
    }
  }
  try {
    check_time_history_range(*r.scene, before_mm, after_mm);
  } catch (const InputError& error) {
    throw InputError(error.file(), error.key() == "--before-mm" ? "before_mm" : "after_mm", error.message());
  }
  const double v = r.scene->wheel.speed_m_per_s;
  // The GIL released and Ctrl-C polled, as simulate() (interruptible_run.h): 1e7 samples take seconds.
  TimeHistory history = interruptible("railjoint.Prediction.time_history", [&] {
    return impact_time_history(r.scene->joint, r.scene->wheel, r.prediction, before_mm * 1e-3 / v,
                               after_mm * 1e-3 / v, samples);
  });
  return column_arrays(time_history_table(std::move(history), r.prediction, v));
}

}  // namespace

void bind_prediction_class(py::module_& m) {
  py::class_<PredictionResult> c(m, "Prediction", R"doc(
The kinematic model's answer for one joint and wheel (thesis ch. 3-4):
contact scenario, transition value y_t, contact point A, the vertical
momentum jump Delta p_z = M (zdot+ - zdot-) in three forms. Coordinates in
the joint frame: x along the track (0 at the bottom of the dip), y lateral
(0 on the rail-head centre line), z up; SI units, each in the field's name.
Missing values (no real value, not applicable) are None.
)doc");
  using P = ImpactPrediction;
  field(c, "scenario", [](const P& p) -> py::object {
    if (p.scenario == ImpactScenario::step) return py::str("step");
    return py::int_(p.scenario == ImpactScenario::one ? 1 : 2);
  }, "Contact scenario: 1 (plain V, |y_w| <= y_t), 2 (the wheel strikes the cut edge at A), or \"step\"");
  field(c, "on_landing", [](const P& p) { return p.on_landing; },
        "True when the jump happens on landing after a step down (y_w < 0 in scenario 2, u0 < 0)");
  field(c, "y_t_m", [](const P& p) { return finite_or_none(p.transition_y_m); },
        "Transition value y_t = R sin(beta/2) tan(theta) [m]; None for a square joint");
  field(c, "governing_y_m", [](const P& p) { return p.governing_y_m; },
        "Lateral position of the wheel slice that governs the impact [m]");
  field(c, "configuration", [](const P& p) { return p.configuration ? py::object(py::int_(*p.configuration)) : py::none(); },
        "Configuration 1-5 of a finite-width wheel (thesis fig. 3.21); None for a thin disc and a step");
  field(c, "line_contact_length_m", [](const P& p) { return p.line_contact_length_m; },
        "Scenario-1 line-contact length of a cylinder [m] (0: point contact)");
  field(c, "x_A_m", [](const P& p) { return p.x_A_m; },
        "Horizontal distance from the wheel centre line to contact point A, exact solve [m]");
  field(c, "x_A_thesis_m", [](const P& p) { return finite_or_none(p.x_A_thesis_m); },
        "The same by the thesis's closed form (appendix C) [m]; None where it does not apply");
  field(c, "alpha_rad", [](const P& p) { return p.alpha_rad; }, "alpha, sin(alpha) = x_A / R, exact [rad]");
  field(c, "alpha_thesis_rad", [](const P& p) { return finite_or_none(p.alpha_thesis_rad); },
        "alpha from the thesis's closed form of x_A [rad]; None where it does not apply");
  field(c, "impact_x_m", [](const P& p) { return p.impact_wheel_x_m; }, "Wheel-centre x at the two-point contact [m]");
  field(c, "impact_z_m", [](const P& p) { return p.impact_wheel_z_m; }, "Wheel-centre z at the two-point contact [m]");
  field(c, "contact_A_m", [](const P& p) { return point_or_none(p.contact_A_m); },
        "Contact point A on the rail the wheel meets, (x, y, z) [m] (thesis fig. 4.8)");
  field(c, "contact_B_m", [](const P& p) { return point_or_none(p.contact_B_m); },
        "Contact point B on the rail the wheel leaves, (x, y, z) [m]");
  field(c, "zdot_before_m_per_s", [](const P& p) { return p.zdot_before_m_per_s; },
        "Exact vertical velocity of the wheel centre just before the jump [m/s]");
  field(c, "zdot_after_m_per_s", [](const P& p) { return p.zdot_after_m_per_s; },
        "Exact vertical velocity just after the jump [m/s]");
  field(c, "exact_Ns", [](const P& p) { return p.impulse.exact_Ns; },
        "Jump Delta p_z, exact geometry with the horizontal speed v held (the simulation's target) [N s]");
  field(c, "thesis_Ns", [](const P& p) { return finite_or_none(p.impulse.thesis_Ns); },
        "Jump as printed in the thesis (sin forms; eq. 3.6 for a step) [N s]; None where it has no real value");
  field(c, "small_angle_Ns", [](const P& p) { return p.impulse.small_angle_Ns; },
        "Jump in the small-angle form (M beta v, M v (alpha + beta/2), M v sqrt(2 u0 / R)) [N s]");
  c.def("as_dict", &prediction_dict,
        "The prediction as `railjoint analytic SCENE --json` prints it, parsed (dict; SI units, each key's "
        "unit in its name, scenes/report/outputs.md); with the \"scene\" block for analytic()'s result");
  c.def("time_history", &time_history, py::arg("before_mm") = 10.0, py::arg("after_mm") = 12.0,
        py::arg("samples") = 2001, R"doc(
The kinematic time history about the impact (thesis figs. 3.7, 4.5), as
`railjoint analytic SCENE --csv FILE --before-mm B --after-mm A --samples N`
writes it: a dict from each column to a read-only float64 NumPy array of the
computed doubles (no text between; -0.0 as 0.0, as the CSV writes it). t_s (0 at the impact), x_m, z_exact_m, zdot_exact_m_per_s,
z_linear_m, zdot_linear_m_per_s (the thesis's linearised path; None where
the thesis's jump has no real value, thesis_Ns None: a crown, a cone, a gap),
momentum_exact_Ns, impulse_exact_Ns (scenes/report/outputs.md).

before_mm : travel covered before the impact [mm]
after_mm  : travel covered after it [mm]
samples   : points, evenly spaced in time
Raises ValueError (the CLI's message, naming the argument) for a travel
outside [0, 100000] mm or one that would take the wheel off the rails.
Ctrl-C stops a long one with KeyboardInterrupt.
)doc");
  c.def(
      "time_history_frame",
      [](const py::object& self, double before_mm, double after_mm, int samples) {
        return columns_frame(self.attr("time_history")(before_mm, after_mm, samples),
                             "railjoint.Prediction.time_history_frame()", "Prediction.time_history()");
      },
      py::arg("before_mm") = 10.0, py::arg("after_mm") = 12.0, py::arg("samples") = 2001,
      "time_history() as a pandas.DataFrame: the same columns in --csv's order, float64, a None column all NaN "
      "(pandas imported on first use; ImportError without it)");
  c.def("__repr__", [](const py::object& self) {
    return "railjoint.Prediction(scenario=" + std::string(py::repr(self.attr("scenario"))) +
           ", exact_Ns=" + std::string(py::repr(self.attr("exact_Ns"))) + ")";
  });
  // A copy is the same prediction (its scene is shared: neither changes);
  // pickle carries its values (frozen_result.h).
  c.def("__copy__", [](const PredictionResult& r) { return r; });
  c.def("__deepcopy__", [](const PredictionResult& r, const py::dict&) { return r; });
  add_frozen_pickle(c, nullptr);
}

void bind_analytic(py::module_& m) {
  bind_prediction_class(m);
  static const std::string doc = command_doc(R"doc(The kinematic model of the scene's joint and wheel (no simulation, no Bullet
world): scenario, y_t [m], x_A [m], alpha [rad], contact points A and B [m],
the jump in three forms [N s]. A few microseconds.

scene : a Scene (load_scene() or Scene(...)); its [joint] and [wheel] are read
Raises ValueError, with the CLI's message, for a case outside the model
(|y_w| > b_t, a gap the wheel drops into, ...).
Prediction.as_dict() equals `railjoint analytic SCENE --json`.
)doc", "analytic");
  m.def("analytic", &analytic, py::arg("scene"), doc.c_str());
}

}  // namespace railjoint::python
