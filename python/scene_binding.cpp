// railjoint.Scene and railjoint.load_scene: scenes made in Python, read by the
// CLI's scene reader (python_scene.h).

#include <filesystem>
#include <stdexcept>
#include <set>
#include <sstream>

#include <pybind11/stl.h>
#include <toml++/toml.h>

#include "bindings.h"
#include "json_dict.h"
#include "path_argument.h"
#include "python_scene.h"
#include "scene_values.h"
#include "scenes/input_file.h"
#include "scenes/report/scene_json.h"
#include "support/input_error.h"

namespace py = pybind11;

namespace railjoint::python {

namespace {

// What stands for the file in the messages of a scene made from dicts.
constexpr const char* kDictSceneName = "scene";

// Keys given True/False: the reader's refusal of one (a number key) is a
// TypeError, as Python refuses a value of the wrong type.
using BooleanKeys = std::set<std::string>;

std::vector<std::string> override_texts(const py::object& overrides, const std::string& file, BooleanKeys& booleans) {
  std::vector<std::string> texts;
  if (overrides.is_none()) return texts;
  for (const auto& [key, value] : overrides.cast<py::dict>()) {
    const std::string name = py::str(key);
    if (name.find_first_of("\n\r=") != std::string::npos) {
      throw InputError(file, name, "is not a key: give each key its own entry, its value as the entry's value");
    }
    texts.push_back(name + "=" + override_text(value, file, name));
    if (is_boolean(value)) booleans.insert(name);
  }
  return texts;
}

std::shared_ptr<PythonScene> read_scene(SceneSource source, const BooleanKeys& booleans) {
  try {
    return std::make_shared<PythonScene>(std::move(source));
  } catch (const InputError& error) {
    if (booleans.count(error.key()) != 0) throw py::type_error(error.what());
    throw;
  }
}

std::shared_ptr<PythonScene> scene_from_file(const py::object& path_like, const py::object& overrides,
                                             const std::vector<std::string>& unsets) {
  const std::string path = path_argument(path_like, "path");
  BooleanKeys booleans;
  std::vector<std::string> texts = override_texts(overrides, path, booleans);
  return read_scene(SceneSource{read_input_file(path, "scene"), path, std::move(texts), unsets}, booleans);
}

// Scene(name=..., joint={...}, wheel={...}): a TOML table written from the
// dicts, read as a file named "scene" would be.
std::shared_ptr<PythonScene> scene_from_sections(const py::kwargs& sections) {
  toml::table root;
  BooleanKeys booleans;
  for (const auto& [section, keys] : sections) {
    const std::string name = py::str(section);
    if (!py::isinstance<py::dict>(keys)) {
      insert_scene_value(root, name, keys, kDictSceneName, name);  // name = "...", description = "..."
      if (is_boolean(keys)) booleans.insert(name);
      continue;
    }
    toml::table table;
    for (const auto& [key, value] : keys.cast<py::dict>()) {
      const std::string key_name = py::str(key);
      insert_scene_value(table, key_name, value, kDictSceneName, name + "." + key_name);
      if (is_boolean(value)) booleans.insert(name + "." + key_name);
    }
    root.insert_or_assign(name, std::move(table));
  }
  std::ostringstream text;
  text << root;
  return read_scene(SceneSource{text.str(), kDictSceneName, {}, {}}, booleans);
}

std::string scene_repr(const PythonScene& scene) {
  const Scene& s = scene.keys();
  std::string text = "railjoint.Scene(name=" + std::string(py::repr(py::str(s.name))) +
                     ", file=" + std::string(py::repr(path_text(s.file)));
  if (!scene.source().overrides.empty()) {
    text += ", overrides=[";
    for (std::size_t i = 0; i < scene.source().overrides.size(); ++i) {
      text += (i ? ", " : "") + std::string(py::repr(py::str(scene.source().overrides[i])));
    }
    text += "]";
  }
  return text + ")";
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<PythonScene, std::shared_ptr<PythonScene>>(m, "Scene", R"doc(
A scene: the joint, the wheel and the settings of one run, as a scene file
(TOML) describes them. Every key, default, unit and check is the scene
reader's, the one the CLI uses (`railjoint --help` lists the keys):

    Scene(joint={"theta_deg": 45.0, "beta": 0.03},   # [joint] of a scene file
          wheel={"y": 0.015, "speed": 30.0},         # [wheel]: SI units (m, kg, m/s)
          sim={"time_step": 5e-5})                   # [sim], [contact_patch], [render] ...

Each keyword is a section (a dict of its keys) or a top-level key (name,
description). Keys left out take the thesis's values. A bad key, type or
range raises ValueError with the CLI's message, the file named "scene":
"scene: key 'wheel.y': must be in [-1, 1] m, got 15 (...)". A case the
kinematic model refuses (|y_w| > b_t, ...) raises when analytic() or
simulate() first checks it, as the CLI's commands do.
)doc")
      .def(py::init(&scene_from_sections))
      .def_property_readonly("name", [](const PythonScene& s) { return s.keys().name; },
                             "The scene's name: its `name` key, else the file's stem (str)")
      .def_property_readonly("file", [](const PythonScene& s) { return path_text(s.keys().file); },
                             "The file it was read from as named, or \"scene\" for a scene made from dicts (str)")
      .def_property_readonly("description", [](const PythonScene& s) { return s.keys().description; },
                             "Its `description` key (str)")
      .def_property_readonly("overrides", [](const PythonScene& s) { return s.source().overrides; },
                             "The --set overrides applied to the file, as \"section.key=value\" texts (list of str)")
      .def_property_readonly(
          "given_keys",
          [](const PythonScene& s) { return std::vector<std::string>(s.keys().given_keys.begin(), s.keys().given_keys.end()); },
          "The keys the file, the dicts or an override gave, \"section.key\" (sorted list of str); the others "
          "hold their defaults")
      .def(
          "as_dict", [](const PythonScene& s) { return report_dict(scene_json(s.keys())); },
          "Every key the reader read with the value it holds, defaults included, in the file's units "
          "(theta_deg in degrees): the \"scene\" block of `railjoint pressure --json` (dict). Keys derived "
          "for a run (joint.length) are listed under \"derived\" in the reports of analytic() and simulate().")
      .def("__repr__", &scene_repr)
      // A scene never changes: a copy is the scene itself; pickle carries
      // what it was made from (the TOML text, the file's name, the --set and
      // --unset keys, and the folders its relative profile paths are read
      // from) and reads it again, as the CLI would. Without the folders an
      // unpickled scene read its profile from the folder current then: a
      // same-named file there gave 1125.08 N s instead of 1275.05.
      .def("__copy__", [](const std::shared_ptr<PythonScene>& s) { return s; })
      .def("__deepcopy__", [](const std::shared_ptr<PythonScene>& s, const py::dict&) { return s; })
      .def(py::pickle(
          [](const PythonScene& s) {
            const SceneSource& source = s.source();
            return py::make_tuple(py::bytes(source.text), py::bytes(source.name), source.overrides, source.unsets,
                                  py::bytes(s.scene_folder().string()), py::bytes(s.overrides_folder().string()));
          },
          [](const py::tuple& state) {
            if (state.size() != 6) throw std::invalid_argument("not the pickled state of a railjoint.Scene");
            return std::make_shared<PythonScene>(
                SceneSource{state[0].cast<std::string>(), state[1].cast<std::string>(),
                            state[2].cast<std::vector<std::string>>(), state[3].cast<std::vector<std::string>>()},
                std::filesystem::path(state[4].cast<std::string>()), std::filesystem::path(state[5].cast<std::string>()));
          }));

  m.def("load_scene", &scene_from_file, py::arg("path"), py::arg("overrides") = py::none(),
        py::arg("unsets") = std::vector<std::string>{}, R"doc(
Reads a scene file (TOML), as `railjoint COMMAND path --set k=v --unset k` does.

path      : the scene file (str, bytes or os.PathLike), e.g. "scenes/default.toml"
overrides : {"section.key": value}, each one a --set, e.g. {"wheel.speed": 10.0}
            (10 m/s); a float, int or bool is set as that TOML value, a str as
            the command line gives it ("step" is text, "30" a number)
unsets    : ["section.key", ...], each one an --unset: the file's key is dropped
            and takes its default

Returns a Scene. Raises ValueError with the CLI's message (the file, the key
and the allowed range with its unit) for a missing file, bad TOML, an
unknown key, a value out of range, a text with a line break, or a NUL in
path; TypeError naming the key for a Python value no key takes (a list, an
array of other than one value, True for a number key). A NumPy scalar or
one-element array is the value it holds.
)doc");
}

}  // namespace railjoint::python
