// The Python module `railjoint`: the scene reader, the kinematic model, the
// simulation, the local model and sweeps of the `railjoint` CLI, called
// in-process (no process per run), results as dicts, NumPy arrays and pandas
// tables. Importing it loads no GL and no MPI.

#include "bindings.h"
#include "support/input_error.h"

namespace py = pybind11;

PYBIND11_MODULE(railjoint, m) {
  m.doc() = R"doc(
railjoint: the vertical impact of a train wheel crossing an inclined dipped
rail joint (L. Engel, MSc thesis, TU Delft, 2024), from Python.

    import railjoint
    scene = railjoint.load_scene("scenes/default.toml", overrides={"wheel.speed": 30.0})
    railjoint.analytic(scene).exact_Ns      # the kinematic model's jump [N s]
    run = railjoint.simulate(scene)         # the Bullet crossing
    run.jump_Ns, run.error_exact, run.trajectory["z_m"]
    railjoint.sweep(scene, {"joint.theta_deg": [30, 45, 60]}, run=["analytic", "simulate"])

Scenes are read by the CLI's scene reader (same keys, defaults, units and
messages as the TOML files and --set); as_dict() of every result equals the
CLI's --json output. SI units throughout, each in the field's name.
)doc";
  m.attr("__version__") = RAILJOINT_VERSION;
  // Bad input is a ValueError with the CLI's message; a path in it is the
  // file name's bytes, decoded as Python decodes file names (a non-UTF-8
  // name keeps its bytes as surrogates instead of failing to decode).
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const railjoint::InputError& error) {
      const py::object text = py::reinterpret_steal<py::object>(PyUnicode_DecodeFSDefault(error.what()));
      if (text) PyErr_SetObject(PyExc_ValueError, text.ptr());
    }
  });
  railjoint::python::bind_scene(m);
  railjoint::python::bind_analytic(m);
  railjoint::python::bind_simulate(m);
  railjoint::python::bind_pressure(m);
  railjoint::python::bind_sweep(m);
  railjoint::python::bind_contact(m);
}
