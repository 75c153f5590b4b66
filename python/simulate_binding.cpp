// railjoint.Simulation and railjoint.simulate(scene): the Bullet crossing, as
// `railjoint simulate` runs it, with the GIL released while it runs.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cli_help.h"
#include "column_arrays.h"
#include "frozen_result.h"
#include "interruptible_run.h"
#include "json_dict.h"
#include "models/jump_error.h"
#include "prediction_result.h"
#include "python_scene.h"
#include "result_values.h"
#include "scenes/report/force_run_numbers.h"
#include "scenes/report/prediction_json.h"
#include "scenes/report/scene_json.h"
#include "scenes/report/simulation_csv.h"
#include "scenes/report/simulation_json.h"
#include "sim/simulate_crossing.h"
#include "sim/time_origin.h"
#include "support/no_negative_zero.h"

namespace py = pybind11;

namespace railjoint::python {

namespace {

struct SimulationRun {
  std::shared_ptr<const Scene> scene;
  SimulationResult result;
  double t0_s = 0.0;            ///< run time of the outputs' t = 0 (sim/time_origin.h)
  std::optional<ForceRunNumbers> forces;  ///< a force run's P0, P1, P2, ...; none off a force run
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
  const InertialOutcome* inertial = run->result.inertial();
  if (inertial && inertial->forces) run->forces = force_run_numbers(run->result);
  return run;
}

py::object simulation_dict(const SimulationRun& run) {
  if (run.frozen) return frozen_report(run.frozen);
  nlohmann::json report = simulation_json(run.result);
  report["scene"] = scene_json(*run.scene);
  return report_dict(report);
}

py::object trajectory(SimulationRun& run) {
  return columns_on_first_use(run.frozen, run.trajectory, [&] { return column_arrays(simulation_table(run.result)); });
}

template <class Get>
void field(py::class_<SimulationRun, std::shared_ptr<SimulationRun>>& c, const char* name, Get get, const char* doc) {
  add_result_property(c, name, [get](const SimulationRun& run) { return get(run, run.result); }, doc);
}

// A force run's number (scenes/report/force_run_numbers.h) as Python holds
// it: None off a force run and where the run has none (NaN there), zero
// without a sign as the JSON writes it; a time from the run's clock to the
// outputs' (t0_s), as the JSON's.
py::object force_number(const SimulationRun& run, double ForceRunNumbers::*number, bool from_run_clock = false) {
  if (!run.forces) return py::none();
  double value = (*run.forces).*number;
  if (from_run_clock) value -= run.t0_s;
  if (value != value) return py::none();
  return py::float_(without_sign_on_zero(value));
}

template <class T>
py::object force_value(const SimulationRun& run, T ForceRunNumbers::*value) {
  return run.forces ? py::cast((*run.forces).*value) : py::none();
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
  // A force run's numbers, as `simulate --json` writes them under sim.forces
  // and the study tables read them (ForceRunNumbers); None off a force run.
  using N = ForceRunNumbers;
  const auto force = [&c](const char* name, double N::*number, const char* doc, bool from_run_clock = false) {
    field(
        c, name, [number, from_run_clock](const S& s, const R&) { return force_number(s, number, from_run_clock); },
        doc);
  };
  force("p0_N", &N::static_N, "A force run's static force P0 = sim.wheel_load + M g [N] (sim.forces.static_N); None "
        "off a force run, as every force field");
  force("p1_N", &N::p1_N, "P1, the largest contact force (a bogie's leading wheel) [N]");
  force("p1_time_s", &N::p1_time_s, "When P1 happened [s]", true);
  force("p2_N", &N::p2_N, "P2, the largest after the low pass [N]; None when none (a rigid track)");
  force("p2_time_s", &N::p2_time_s, "When P2 happened [s]", true);
  force("jenkins_p1_N", &N::jenkins_p1_N, "Jenkins's P1 for the scene's track [N]; None where none");
  force("jenkins_p2_N", &N::jenkins_p2_N, "Jenkins's P2 [N]; None where none");
  force("p2_rail_seat_N", &N::p2_rail_seat_N, "P2 of the rail-seat (pad) force, picked as P2 is [N]; None on a "
        "rigid track");
  force("rail_seat_peak_N", &N::rail_seat_peak_N, "The rail-seat force's largest value [N]; None on a rigid track");
  force("ballast_peak_N", &N::ballast_peak_N, "The ballast force's largest value [N]; None on a rigid track");
  force("flight_time_s", &N::flight_time_s, "Time the wheel was off the rail after the impact, all flights [s]");
  force("longest_flight_s", &N::longest_flight_s, "The longest flight [s]");
  force("track_mass_p1_kg", &N::reading_m_T1_kg, "Effective track mass for Jenkins's P1 [kg] (sim.forces.jenkins; "
        "the discrete track's equivalent lumped track); None on a rigid track");
  force("track_mass_p2_kg", &N::reading_m_T_kg, "Effective track mass for Jenkins's P2 [kg]");
  force("track_stiffness_N_per_m", &N::reading_K_T_N_per_m, "Track stiffness as Jenkins reads it [N/m]");
  force("track_damping_N_s_per_m", &N::reading_C_T_N_s_per_m, "Track damping as Jenkins reads it [N s/m]");
  field(
      c, "p2_after_p1", [](const S& s, const R&) { return force_value(s, &N::p2_after_p1); },
      "P2 is a peak of its own after P1 (False: the two merged into one low-passed hump)");
  field(
      c, "p2_across_flight", [](const S& s, const R&) { return force_value(s, &N::p2_across_flight); },
      "A flight began between the impact and P2: P2 spans contact loss, no track force");
  field(
      c, "flight_count", [](const S& s, const R&) { return force_value(s, &N::flights); },
      "Flights, contact lost after the impact (sim.forces.flights)");
  c.def_property_readonly("trajectory", &trajectory, R"doc(
The time series, one entry per recorded sample: a dict from each column of
`railjoint simulate --csv` to a read-only float64 NumPy array holding the
computed doubles (no text between; -0.0 as 0.0, as the CSV writes it).
Columns: t_s (outputs' clock), x_m, z_m (wheel centre, joint frame),
zdot_m_per_s, contacts (count), contact_impulse_z_Ns (summed vertical contact
impulse of the step), xdot_m_per_s, contact_force_z_N (impulse / time it bore the load),
z_kinematic_m (the kinematic centre height at x), spin_rate_rad_per_s; a force
run adds rail_z_m, sleeper_z_m, sprung_z_m, contact_y_m (NaN in flight), on
an elastic track rail_seat_N and ballast_N, under a bogie
wheel0_contact_force_z_N and wheel1_contact_force_z_N
(scenes/report/outputs.md). Made on first use, then kept.
)doc");
  c.def(
      "trajectory_frame",
      [](const py::object& self) {
        return columns_frame(self.attr("trajectory"), "railjoint.Simulation.trajectory_frame()",
                             "Simulation.trajectory");
      },
      "The trajectory as a pandas.DataFrame: the same columns in --csv's order, float64 (pandas imported on "
      "first use; ImportError without it)");
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
