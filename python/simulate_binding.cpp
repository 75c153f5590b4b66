// railjoint.Simulation and railjoint.simulate(scene): the Bullet crossing, as
// `railjoint simulate` runs it, with the GIL released while it runs.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cli_help.h"
#include "exact_csv_stream.h"
#include "frozen_result.h"
#include "interruptible_run.h"
#include "json_dict.h"
#include "models/jump_error.h"
#include "prediction_result.h"
#include "python_scene.h"
#include "result_values.h"
#include "scenes/report/prediction_json.h"
#include "scenes/report/scene_json.h"
#include "scenes/report/simulation_csv.h"
#include "scenes/report/simulation_json.h"
#include "sim/simulate_crossing.h"
#include "sim/time_origin.h"

namespace py = pybind11;

namespace railjoint::python {

namespace {

struct SimulationRun {
  std::shared_ptr<const Scene> scene;
  SimulationResult result;
  double t0_s = 0.0;            ///< run time of the outputs' t = 0 (sim/time_origin.h)
  py::object trajectory;        ///< the columns, made on first use
  py::object frozen;            ///< an unpickled run's state (frozen_result.h); null otherwise
};

std::shared_ptr<SimulationRun> simulate(const PythonScene& scene) {
  auto run = std::make_shared<SimulationRun>();
  run->scene = scene.checked(SceneCheck::simulation);
  const Scene& s = *run->scene;
  // The GIL released: other Python threads run their own crossings meanwhile.
  run->result = interruptible("railjoint.simulate", [&] {
    return naming_scene_file(s, [&] { return simulate_crossing(s.crossing); });
  });
  run->t0_s = simulation_time_origin_s(run->result);
  return run;
}

py::object simulation_dict(const SimulationRun& run) {
  if (run.frozen) return frozen_report(run.frozen);
  nlohmann::json report = simulation_json(run.result);
  report["scene"] = scene_json(*run.scene);
  return report_dict(report);
}

py::object trajectory(SimulationRun& run) {
  if (run.frozen) return frozen_columns(run.frozen);
  return cached_csv_columns(
      run.trajectory, [&](std::ostream& csv) { write_simulation_csv(run.result, csv); },
      run.result.trajectory.samples.size());
}

template <class Get>
void field(py::class_<SimulationRun, std::shared_ptr<SimulationRun>>& c, const char* name, Get get, const char* doc) {
  c.def_property_readonly(
      name,
      [get, name](const SimulationRun& run) -> py::object {
        return run.frozen ? frozen_field(run.frozen, name) : as_python(get(run, run.result));
      },
      doc);
}

// A history as a read-only float64 NumPy array (its own copy).
py::array_t<double> read_only_array(const std::vector<double>& values) {
  py::array_t<double> array(static_cast<py::ssize_t>(values.size()), values.data());
  array.attr("flags").attr("writeable") = false;
  return array;
}

// A force run's track supports (sim/force_outcome.h): the lumped track's
// one, each discrete support recorded near the joint; None on a rigid track
// or off a force run.
py::object supports(const SimulationResult& r) {
  const InertialOutcome* inertial = r.inertial();
  if (!inertial || !inertial->forces || !inertial->forces->support) return py::none();
  const ForceOutcome& f = *inertial->forces;
  py::list out;
  const auto entry = [&](py::object x_m, const std::vector<double>& seat_N, const std::vector<double>& ballast_N,
                         double seat_static_N, double ballast_static_N) {
    py::dict d;
    d["x_m"] = x_m;
    d["rail_seat_N"] = read_only_array(seat_N);
    d["ballast_N"] = read_only_array(ballast_N);
    d["rail_seat_static_N"] = seat_static_N;
    d["ballast_static_N"] = ballast_static_N;
    out.append(d);
  };
  if (f.supports.empty()) {
    const TrackSupportOutcome& s = *f.support;
    entry(py::none(), s.rail_seat_N, s.ballast_N, s.rail_seat_static_N, s.ballast_static_N);
  }
  for (const SupportHistory& h : f.supports) {
    entry(py::float_(h.x_m), h.rail_seat_N, h.ballast_N, h.rail_seat_static_N, h.ballast_static_N);
  }
  return out;
}

}  // namespace

// A value of the joint's impact, or None when none was found.
template <class Read>
py::object impact_or_none(const SimulationResult& r, Read read) {
  return r.impact ? py::object(py::float_(read(*r.impact))) : py::none();
}

void bind_simulate(py::module_& m) {
  py::class_<SimulationRun, std::shared_ptr<SimulationRun>> c(m, "Simulation", R"doc(
A simulated crossing (Bullet, double precision): the measured vertical
momentum jump, its errors against the three analytic forms, the run's own
verdict, and the time series. Times on the outputs' clock: t = 0 when the
wheel centre passes the predicted impact position. SI units, each in the
field's name; what was not measured (no impact found) is None.
)doc");
  using R = SimulationResult;
  using S = SimulationRun;
  field(
      c, "mode", [](const S&, const R& r) { return r.inertial() ? "inertial" : "kinematic"; },
      "sim.mode of the run: \"kinematic\" (held on the rail up to the impact) or \"inertial\"");
  field(
      c, "impact_found", [](const S&, const R& r) { return r.impact_found(); },
      "Whether an impact was found at the joint");
  field(c, "verdict", [](const S&, const R& r) { return r.verdict.ok ? "ok" : "suspect"; },
        "The run's own check (sim/self_check.h): \"ok\", or \"suspect\" when it cannot vouch for its jump (the CLI "
        "then exits 1)");
  field(c, "verdict_reason", [](const S&, const R& r) { return r.verdict.reason; },
        "Why the run is suspect, every failed check \"; \"-separated (\"\" when ok)");
  field(
      c, "jump_Ns", [](const S&, const R& r) { return measured_or_none(r.impact_found(), r.impulse_Ns()); },
      "Measured jump M (zdot+ - zdot-) at the impact, both sides extrapolated to it [N s]");
  field(
      c, "jump_from_contacts_Ns",
      [](const S&, const R& r) {
        return impact_or_none(r, [](const JointImpact& i) { return i.impulse_from_contacts_Ns(); });
      },
      "The same from the summed vertical contact impulses [N s]");
  field(
      c, "impact_time_s",
      [](const S& s, const R& r) {
        return impact_or_none(r, [&s](const JointImpact& i) { return i.time_s() - s.t0_s; });
      },
      "When the impact happened [s]");
  field(
      c, "impact_x_m",
      [](const S&, const R& r) { return impact_or_none(r, [](const JointImpact& i) { return i.wheel_x_m(); }); },
      "Wheel-centre x at the impact [m]");
  field(
      c, "zdot_before_m_per_s",
      [](const S&, const R& r) {
        return impact_or_none(r, [](const JointImpact& i) { return i.zdot_before_m_per_s(); });
      },
      "Vertical velocity just before the impact (extrapolated) [m/s]");
  field(
      c, "zdot_after_m_per_s",
      [](const S&, const R& r) {
        return impact_or_none(r, [](const JointImpact& i) { return i.zdot_after_m_per_s(); });
      },
      "Vertical velocity just after the impact (extrapolated) [m/s]");
  field(
      c, "contact_struck_m",
      [](const S&, const R& r) { return r.impact ? point_or_none(r.impact->struck_point_m()) : py::none(); },
      "Contact point struck at the impact, (x, y, z) [m] (against the prediction's contact_A_m)");
  field(
      c, "contact_left_m",
      [](const S&, const R& r) { return r.impact ? point_or_none(r.impact->left_point_m()) : py::none(); },
      "Contact point left at the impact, (x, y, z) [m] (against the prediction's contact_B_m)");
  field(c, "max_penetration_m", [](const S&, const R& r) { return r.max_penetration_m; },
        "Largest overlap of wheel and rail over the run [m]");
  field(
      c, "liftoff", [](const S&, const R& r) { return r.liftoff_time_s().has_value(); },
      "Whether the wheel left the rails after the impact");
  field(
      c, "liftoff_time_s",
      [](const S& s, const R& r) {
        return r.liftoff_time_s() ? py::object(py::float_(*r.liftoff_time_s() - s.t0_s)) : py::none();
      },
      "When it left them [s]");
  field(
      c, "second_impact", [](const S&, const R& r) { return r.second_impact.has_value(); },
      "Whether it landed again within the run");
  field(
      c, "second_impact_time_s",
      [](const S& s, const R& r) {
        return r.second_impact ? py::object(py::float_(r.second_impact->time_s - s.t0_s)) : py::none();
      },
      "When it landed again [s]");
  field(
      c, "second_jump_Ns",
      [](const S&, const R& r) {
        return r.second_impact ? py::object(py::float_(r.second_impact->impulse_Ns)) : py::none();
      },
      "The jump of that landing [N s]");
  field(
      c, "preload_N", [](const S&, const R& r) { return r.model->load_N; },
      "Downward force on the wheel besides gravity (inertial mode: the wheel load) [N]");
  field(c, "steps", [](const S&, const R& r) { return r.steps; }, "Simulation steps taken");
  field(c, "refined_steps", [](const S&, const R& r) { return r.refined_steps; }, "Of them, refined (short) steps");
  field(c, "wall_time_s", [](const S&, const R& r) { return r.wall_seconds; },
        "Wall time of building the world and stepping, one core [s]");
  field(
      c, "error_exact",
      [](const S&, const R& r) {
        return measured_or_none(r.impact_found(), jump_errors(r.impulse_Ns(), r.prediction().impulse).exact);
      },
      "Relative error of the measured jump against the exact form, (measured - form) / form [-], for the wheel as "
      "simulated (analytic_as_simulated)");
  field(
      c, "error_thesis",
      [](const S&, const R& r) {
        return measured_or_none(r.impact_found(), jump_errors(r.impulse_Ns(), r.prediction().impulse).thesis);
      },
      "Relative error against the thesis's printed form [-]");
  field(
      c, "error_small_angle",
      [](const S&, const R& r) {
        return measured_or_none(r.impact_found(), jump_errors(r.impulse_Ns(), r.prediction().impulse).small_angle);
      },
      "Relative error against the small-angle form [-]");
  field(
      c, "analytic",
      [](const S&, const R& r) {
        const ImpactPrediction& p = r.model->thin_disc_prediction ? *r.model->thin_disc_prediction : r.prediction();
        nlohmann::json block = analytic_block_to_json(r.model->joint, r.model->wheel, p);
        block["profile_smoothing"] = profile_smoothing_json(r.model->joint, r.model->wheel, p);
        return PredictionResult{p, nullptr, block["profile_smoothing"], block};
      },
      "The scene's prediction (Prediction; as `analytic`: a thin disc stays a thin disc)");
  field(
      c, "analytic_as_simulated",
      [](const S&, const R& r) {
        return PredictionResult{r.prediction(), nullptr};
      },
      "The prediction for the wheel Bullet holds, which the errors are against (a thin disc is simulated as a "
      "cylinder 2 sim.disc_half_width wide whose inner face governs) (Prediction)");
  field(
      c, "supports", [](const S&, const R& r) { return supports(r); },
      "A force run's track supports (None off a force run or on a rigid track): a list of dicts, x_m (the "
      "sleeper's place [m]; None for the lumped track's one support), rail_seat_N and ballast_N (read-only "
      "float64 NumPy arrays, compression +, with the weights each carries [N], one value per row of "
      "`trajectory`), rail_seat_static_N and ballast_static_N (with P0 standing on the joint). The lumped "
      "track has one; the discrete track the six sleepers nearest the joint, in x order");
  c.def_property_readonly("trajectory", &trajectory, R"doc(
The time series, one entry per recorded sample: a dict from each column of
`railjoint simulate --csv` to a read-only float64 NumPy array, every digit
kept. Columns: t_s (outputs' clock), x_m, z_m (wheel centre, joint frame),
zdot_m_per_s, contacts (count), contact_impulse_z_Ns (summed vertical contact
impulse of the step), xdot_m_per_s, contact_force_z_N (impulse / step),
z_kinematic_m (the kinematic centre height at x), spin_rate_rad_per_s; a force
run adds rail_z_m, sleeper_z_m, sprung_z_m (scenes/report/outputs.md).
)doc");
  c.def("as_dict", &simulation_dict,
        "The run as `railjoint simulate SCENE --json` prints it, parsed (dict): analytic, analytic_as_simulated, "
        "sim (measurements, phases, impacts), error, scene");
  c.def("__repr__", [](const py::object& self) {
    return "railjoint.Simulation(jump_Ns=" + std::string(py::repr(self.attr("jump_Ns"))) +
           ", verdict=" + std::string(py::repr(self.attr("verdict"))) + ")";
  });
  // A copy holds the same run (its columns made again on use); pickle
  // carries its values and columns (frozen_result.h).
  add_run_copy(c, &SimulationRun::trajectory);
  add_frozen_pickle(c, "trajectory");

  static const std::string doc = command_doc(R"doc(Simulates the scene's crossing in Bullet (double precision) and measures the
vertical momentum jump [N s] against the analytic forms; the default scene
takes a fraction of a millisecond. The GIL is released while it runs, so
Python threads can simulate crossings side by side; Ctrl-C stops a long run
(on the main thread) with KeyboardInterrupt within about 0.1 s.

scene : a Scene; its [joint], [wheel], [sim] (and [contact], [track],
        [vehicle] for force runs) are read
Raises ValueError, with the CLI's message, for a case outside the model or
settings that cannot work together. A run that finds no impact or cannot
vouch for its jump is returned as it is (the CLI exits 1): see
Simulation.impact_found and Simulation.verdict.
Simulation.as_dict() equals `railjoint simulate SCENE --json` (but for the
measured wall time); Simulation.trajectory holds the columns of --csv.
)doc", "simulate");
  m.def("simulate", &simulate, py::arg("scene"), doc.c_str());
}

}  // namespace railjoint::python
