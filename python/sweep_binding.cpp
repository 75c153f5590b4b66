// railjoint.sweep(base, axes, run=[...]): a grid of scenes through the sweep
// machinery of `railjoint sweep` (scenes/sweeps/): the axes become a sweep
// file's [axes], the base scene its base, and the rows of its results.csv a
// pandas.DataFrame. The GIL is released while the cases run; Ctrl-C stops
// the sweep between chunks, keeping the rows already written.

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <thread>

#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <toml++/toml.h>

#include "bindings.h"
#include "cli_help.h"
#include "path_argument.h"
#include "python_scene.h"
#include "scene_values.h"
#include "scenes/sweeps/case_models.h"
#include "scenes/sweeps/sweep_file.h"
#include "scenes/sweeps/sweep_runner.h"
#include "support/case_pool.h"
#include "sweep_progress.h"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace railjoint::python {

namespace {

// Stands for the sweep file in messages ("sweep: key 'axes.wheel.yy': ...").
constexpr const char* kSweepFileName = "sweep";

// Thrown from a worker when Ctrl-C was pressed; the KeyboardInterrupt waits in
// the calling thread's Python error indicator.
struct SweepInterrupted {};

// A list, tuple, range or NumPy array: a list axis; a dict: a range axis
// ({"from": a, "to": b, "count": n, "scale": "log"}), as in a sweep file.
// Sets holder["axis"] to the axis's TOML value.
void axis_value(toml::table& holder, const std::string& where, const py::handle& values) {
  if (py::isinstance<py::dict>(values)) {
    toml::table range;
    for (const auto& [range_key, value] : values.cast<py::dict>()) {
      const std::string range_name = py::str(range_key);
      insert_scene_value(range, range_name, value, kSweepFileName, where + "." + range_name);
    }
    range.is_inline(true);  // "wheel.y" = { from = ..., to = ... } under [axes]
    holder.insert_or_assign("axis", std::move(range));
    return;
  }
  if (py::isinstance<py::str>(values) || !py::hasattr(values, "__iter__")) {
    throw InputError(kSweepFileName, where,
                     "takes a list of values or a range {\"from\": a, \"to\": b, \"count\": n}, got " +
                         std::string(py::str(values.get_type().attr("__name__"))));
  }
  toml::array list;
  for (const py::handle& value : values) {
    toml::table item;  // a scalar typed as a scene value, moved into the list
    insert_scene_value(item, "v", value, kSweepFileName, where);
    list.push_back(std::move(*item.get("v")));
  }
  holder.insert_or_assign("axis", std::move(list));
}

// The [axes] table in the dict's order: the sweep takes its axes in the
// file's order (the grid's nesting, the columns), and a TOML table written
// whole would sort them by name.
std::string axes_text(const py::dict& axes) {
  std::string text = "[axes]\n";
  for (const auto& [key, values] : axes) {
    const std::string name = py::str(key);
    toml::table holder;
    axis_value(holder, "axes." + name, values);
    toml::table line;
    line.insert_or_assign(name, std::move(*holder.get("axis")));
    std::ostringstream out;
    out << line;
    text += out.str() + "\n";
  }
  return text;
}

std::string sweep_text(const PythonScene& base, const py::dict& axes, const std::vector<std::string>& models,
                       const py::object& sample, const std::string& name) {
  toml::table root;
  root.insert("name", name);
  root.insert("base", base.source().name);
  toml::array run;
  for (const std::string& model : models) run.push_back(model);
  root.insert("run", std::move(run));
  if (!sample.is_none()) {
    toml::table spec;
    for (const auto& [key, value] : sample.cast<py::dict>()) {
      const std::string key_name = py::str(key);
      insert_scene_value(spec, key_name, value, kSweepFileName, "sample." + key_name);
    }
    root.insert("sample", std::move(spec));
  }
  std::ostringstream text;
  text << root << "\n\n" << axes_text(axes);
  return text.str();
}

// A folder of our own for a sweep without `out`, removed when it is read.
fs::path temporary_folder() {
  std::string pattern = (fs::temp_directory_path() / "railjoint-sweep-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("railjoint.sweep: cannot create a temporary folder");
  return pattern;
}

struct RemovedFolder {
  std::optional<fs::path> path;
  ~RemovedFolder() {
    std::error_code ignored;
    if (path) fs::remove_all(*path, ignored);
  }
};

py::object sweep(const py::object& base_arg, const py::dict& axes, const std::vector<std::string>& models, int jobs,
                 const py::object& sample, const py::object& out, const py::object& progress, const std::string& name) {
  const std::shared_ptr<PythonScene> base = py::isinstance<PythonScene>(base_arg)
                                                ? base_arg.cast<std::shared_ptr<PythonScene>>()
                                                : py::module_::import("railjoint").attr("load_scene")(base_arg)
                                                      .cast<std::shared_ptr<PythonScene>>();
  SweepFile file = parse_sweep_file(sweep_text(*base, axes, models, sample, name), kSweepFileName,
                                    base->resolved_text(), case_model_names());
  file.profiles = base->profile_files();  // the base's profiles as read when the Scene was made
  RemovedFolder temporary;
  SweepRunOptions options;
  if (out.is_none()) {
    temporary.path = temporary_folder();
    options.out_dir = *temporary.path;
  } else {
    options.out_dir = path_argument(out, "out");
  }
  // The CLI's --jobs range; 0 is every core. -1 ran on every core silently.
  if (jobs < 0 || jobs > 4096) {
    throw InputError("sweep", "jobs", "must be 0 (every core) or in [1, 4096], got " + std::to_string(jobs));
  }
  options.jobs = jobs > 0 ? jobs : available_cores();
  options.progress = false;  // the CLI's bar goes to the process's stderr; ours to sys.stderr

  std::optional<SweepProgressBar> bar;
  py::object callback;
  if (py::isinstance<py::bool_>(progress)) {
    if (progress.cast<bool>()) bar.emplace(name);
  } else if (!progress.is_none()) {
    callback = progress;
  }
  const bool shows_progress = bar.has_value() || callback;
  const std::thread::id caller = std::this_thread::get_id();
  std::uint64_t shown = 0;  // read and written with the GIL held
  options.after_chunk = [&](std::uint64_t done, std::uint64_t total) {
    const bool on_caller = std::this_thread::get_id() == caller;  // Python runs signal handlers on its main thread only
    if (!on_caller && !shows_progress) return;
    py::gil_scoped_acquire gil;
    if (on_caller && PyErr_CheckSignals() != 0) throw SweepInterrupted{};
    // A worker reads its count before it waits for the GIL, so another's
    // later count can be shown first (CI saw 45 of 45, then 7 of 45): the
    // progress shown only moves forward.
    if (done <= shown) return;
    shown = done;
    if (bar) bar->show(done, total);
    if (callback) callback(done, total);
  };

  SweepSummary summary;
  try {
    py::gil_scoped_release release;
    summary = run_sweep(file, options);
  } catch (const InputError& error) {
    // The runner names the CLI's option; here it is this function's argument.
    if (error.key() != "--out") throw;
    std::string message = error.message();
    for (std::size_t at = message.find("--out"); at != std::string::npos; at = message.find("--out", at)) {
      message.replace(at, 5, "out=");
    }
    throw InputError(error.file(), "out", message);
  } catch (const SweepInterrupted&) {
    if (bar) bar->finish();
    PyErr_Clear();
    const std::string where = out.is_none() ? "pass out=FOLDER to keep the rows and resume"
                                            : "its rows so far are in " + options.out_dir.string() +
                                                  "; the same call resumes from them";
    PyErr_SetObject(PyExc_KeyboardInterrupt, path_text("railjoint.sweep interrupted: " + where).ptr());
    throw py::error_already_set();
  }
  if (bar) bar->finish();
  // Each number read back to the double the sweep computed: results.csv holds the shortest text that
  // does, but pandas' default parser misreads about half of a sweep's cells by up to 230 ulps.
  py::object frame = py::module_::import("pandas").attr("read_csv")(path_text(summary.results.string()),
                                                                    py::arg("float_precision") = "round_trip");
  if (temporary.path) summary.results = "(a temporary folder, removed: pass out=FOLDER to keep it)";
  frame.attr("attrs")["summary"] = sweep_summary_text(summary);
  return frame;
}

}  // namespace

void bind_sweep(py::module_& m) {
  static const std::string doc = command_doc(R"doc(Runs a grid of scenes through the models of `run`, as `railjoint sweep` runs
a sweep file, and returns the rows of its results.csv as a pandas.DataFrame: the case number, the
swept keys, verdict (ok, suspect, no_impact, failed, rejected), message, each
model's columns (SI units in their names, e.g. analytic.exact_Ns,
simulate.jump_Ns, simulate.error_exact) and wall_ms. Each number is the
double the sweep computed, bit for bit.

base     : a Scene, or the path of a scene file
axes     : {"section.key": values}, one axis per scene key, the grid their
           product: a list (tuple, range, NumPy array) of values, or a range
           {"from": a, "to": b, "count": n} (add "scale": "log"; leave out
           "count" to sample it with `sample`)
run      : the models run on every case: "analytic", "simulate", "pressure",
           "forces"
jobs     : threads running cases (0: every core this process may use); the
           GIL is released while they run
sample   : {"count": N, "seed": S, "method": "latin_hypercube" | "random"}
out      : a folder to keep results.csv in (a rerun resumes from its rows);
           None: a temporary folder, removed (str, bytes or os.PathLike)
progress : True: a bar on sys.stderr (none when sys.stderr is None, as
           under pythonw); a callable: called as f(done, total)
           after each chunk of cases
A bad axis, key or model raises ValueError with the CLI's message; a case
the reader or a model refuses is a row with verdict "rejected" and why.
Ctrl-C stops the sweep within a chunk (about 0.2 s of cases) and raises
KeyboardInterrupt; with `out`, the rows written stay and the same call
resumes. DataFrame.attrs["summary"] holds the CLI's closing lines.
)doc", "sweep");
  m.def("sweep", &sweep, py::arg("base"), py::arg("axes"), py::arg("run") = std::vector<std::string>{"analytic"},
        py::arg("jobs") = 0, py::arg("sample") = py::none(), py::arg("out") = py::none(),
        py::arg("progress") = false, py::arg("name") = "sweep", doc.c_str());
}

}  // namespace railjoint::python
