#include "scenes/sweeps/sweep_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include <toml++/toml.h>

#include "scenes/input_file.h"
#include "scenes/scene_tree.h"
#include "scenes/section_reader.h"
#include "scenes/sweeps/range_value.h"
#include "support/input_error.h"

namespace railjoint {

namespace {

namespace fs = std::filesystem;

const std::set<std::string> kTopLevelKeys = {"name", "description", "base", "run", "axes", "sample", "set"};
const std::set<std::string> kRangeKeys = {"from", "to", "count", "scale"};

// Why kMaxSweepCases, for messages.
std::string sweep_size_reason() {
  return "a sweep holds at most " + std::to_string(kMaxSweepCases) +
         " cases (some 17 bytes of memory each while it runs, and ~200 bytes of results.csv: ~2 GB); split a larger "
         "study into several sweep files, or sample it ([sample])";
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "\"" : ", \"") + name + "\"";
  return list;
}

std::string text_key(const toml::table& root, const std::string& file, const char* key, const std::string& fallback) {
  const toml::node* node = root.get(key);
  if (node == nullptr) return fallback;
  if (!node->is_string()) throw InputError(file, key, "must be a text in quotes");
  return node->as_string()->get();
}

std::vector<std::string> read_models(const toml::table& root, const std::string& file,
                                     const std::vector<std::string>& known) {
  const std::string allowed = "a list of models, each one of " + quoted_list(known) + ", e.g. run = [\"analytic\"]";
  const toml::node* node = root.get("run");
  if (node == nullptr) throw InputError(file, "run", "is missing: " + allowed);
  const toml::array* list = node->as_array();
  if (list == nullptr || list->empty()) throw InputError(file, "run", "must be " + allowed);
  std::vector<std::string> models;
  for (const toml::node& item : *list) {
    const std::string name = item.is_string() ? item.as_string()->get() : std::string();
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      throw InputError(file, "run", "must be " + allowed + (name.empty() ? "" : ", got \"" + name + "\""));
    }
    if (std::find(models.begin(), models.end(), name) != models.end()) {
      throw InputError(file, "run", "names \"" + name + "\" twice");
    }
    models.push_back(name);
  }
  return models;
}

SceneValue scalar_value(const toml::node& node, const std::string& file, const std::string& where) {
  if (node.is_boolean()) return node.as_boolean()->get();
  if (node.is_integer()) return static_cast<long long>(node.as_integer()->get());
  if (node.is_floating_point()) {
    const double value = node.as_floating_point()->get();
    if (!std::isfinite(value)) throw InputError(file, where, "values must be finite");
    return value;
  }
  if (node.is_string()) return node.as_string()->get();
  throw InputError(file, where, "values must be numbers, texts or true/false");
}

double range_number(const toml::table& range, const std::string& file, const std::string& where, const char* key) {
  const toml::node* node = range.get(key);
  if (node == nullptr || !node->is_number()) {
    throw InputError(file, where, std::string("a range needs ") + key + " = a number");
  }
  const double value = node->is_integer() ? static_cast<double>(node->as_integer()->get())
                                          : node->as_floating_point()->get();
  if (!std::isfinite(value)) throw InputError(file, where + "." + key, "must be finite");
  return value;
}

std::vector<SceneValue> expand_range(const SweepAxis& axis, long long count) {
  const auto n = static_cast<std::uint64_t>(count);
  std::vector<SceneValue> values;
  values.reserve(n);
  for (std::uint64_t i = 0; i < n; ++i) {
    values.emplace_back(range_value(axis.from, axis.to, i, n, axis.kind == SweepAxis::Kind::log));
  }
  return values;
}

SweepAxis read_axis(const std::string& section, const std::string& key, const toml::node& node, const std::string& file,
                    bool sampling) {
  SweepAxis axis;
  axis.section = section;
  axis.key = key;
  const std::string where = "axes." + axis.name();
  if (const toml::array* list = node.as_array()) {
    if (list->empty()) throw InputError(file, where, "a list axis needs at least one value");
    for (const toml::node& item : *list) axis.values.push_back(scalar_value(item, file, where));
    return axis;
  }
  const toml::table* range = node.as_table();
  if (range == nullptr) {
    axis.values.push_back(scalar_value(node, file, where));  // one value: the same in every case
    return axis;
  }
  for (const auto& [name, value] : *range) {
    if (!kRangeKeys.contains(std::string(name.str()))) {
      throw InputError(file, where + "." + std::string(name.str()),
                       "unknown key in a range (allowed: from, to, count, scale)");
    }
  }
  axis.from = range_number(*range, file, where, "from");
  axis.to = range_number(*range, file, where, "to");
  axis.kind = SweepAxis::Kind::even;
  if (const toml::node* scale = range->get("scale")) {
    const std::string text = scale->is_string() ? scale->as_string()->get() : std::string();
    if (text != "linear" && text != "log") throw InputError(file, where + ".scale", "must be \"linear\" or \"log\"");
    if (text == "log") axis.kind = SweepAxis::Kind::log;
  }
  if (axis.kind == SweepAxis::Kind::log && !(axis.from > 0.0 && axis.to > 0.0)) {
    throw InputError(file, where, "a log range needs from > 0 and to > 0");
  }
  const toml::node* count = range->get("count");
  if (count == nullptr) {
    if (!sampling) {
      throw InputError(file, where + ".count",
                       "is missing: an even or log range needs count = number of values (or a [sample] section to "
                       "sample the range)");
    }
    axis.sampled = true;
    return axis;
  }
  if (!count->is_integer() || count->as_integer()->get() < 1 ||
      static_cast<std::uint64_t>(count->as_integer()->get()) > kMaxSweepCases) {
    throw InputError(file, where + ".count",
                     "must be an integer in [1, " + std::to_string(kMaxSweepCases) + "]" +
                         (count->is_integer() ? ", got " + std::to_string(count->as_integer()->get()) : std::string()) +
                         ": " + sweep_size_reason());
  }
  axis.values = expand_range(axis, count->as_integer()->get());
  return axis;
}

// The scene keys of a table ([axes], [set]) in the file's order, each read
// by `read`: "section.key" quoted, `section.key` unquoted or a [table.section]
// (one level more). toml++ keeps a table's keys sorted, so the source
// position puts them back in the order the user wrote them.
template <class T, class Read>
std::vector<T> read_keyed(const toml::table& table, const std::string& file, const std::string& table_name,
                          const std::string& example, Read read) {
  struct Placed {
    toml::source_position where;
    T item;
  };
  std::vector<Placed> placed;
  for (const auto& [name, value] : table) {
    const std::string text(name.str());
    const auto dot = text.find('.');
    if (dot != std::string::npos) {
      placed.push_back({value.source().begin, read(text.substr(0, dot), text.substr(dot + 1), value)});
      continue;
    }
    const toml::table* section = value.as_table();
    if (section == nullptr || section->contains("from")) {
      throw InputError(file, table_name + "." + text, "is not named by a scene key section.key, e.g. " + example);
    }
    for (const auto& [key, item_value] : *section) {
      placed.push_back({item_value.source().begin, read(text, std::string(key.str()), item_value)});
    }
  }
  std::stable_sort(placed.begin(), placed.end(), [](const Placed& a, const Placed& b) {
    return a.where.line != b.where.line ? a.where.line < b.where.line : a.where.column < b.where.column;
  });
  std::vector<T> items;
  for (Placed& p : placed) items.push_back(std::move(p.item));
  return items;
}

std::vector<SweepAxis> read_axes(const toml::table& root, const std::string& file, bool sampling) {
  const toml::node* node = root.get("axes");
  if (node == nullptr || !node->is_table() || node->as_table()->empty()) {
    throw InputError(file, "axes", "is missing: a sweep needs an [axes] table of scene keys, e.g. \"wheel.y\" = [0.0, 0.01]");
  }
  return read_keyed<SweepAxis>(*node->as_table(), file, "axes", "\"wheel.y\" = [0.0, 0.01]",
                               [&](const std::string& section, const std::string& key, const toml::node& value) {
                                 return read_axis(section, key, value, file, sampling);
                               });
}

// [set]: one value a key, the same in every case.
std::vector<SceneOverride> read_fixed(const toml::table& root, const std::string& file) {
  const toml::node* node = root.get("set");
  if (node == nullptr) return {};
  if (!node->is_table()) throw InputError(file, "set", "must be a [set] table of scene keys, e.g. \"wheel.speed\" = 30.0");
  return read_keyed<SceneOverride>(
      *node->as_table(), file, "set", "\"wheel.speed\" = 30.0",
      [&](const std::string& section, const std::string& key, const toml::node& value) {
        const std::string where = "set." + section + "." + key;
        if (value.is_array() || value.is_table()) {
          throw InputError(file, where, "takes one value (the same in every case); a list of values is an axis ([axes])");
        }
        return SceneOverride{section, key, scalar_value(value, file, where)};
      });
}

SampleSpec read_sample(const toml::table& table, const std::string& file) {
  SectionReader in(file, "sample", &table);
  SampleSpec sample;
  if (!in.has("count")) throw InputError(file, "sample.count", "is missing: the number of sampled points");
  try {
    sample.count = static_cast<std::uint64_t>(in.integer("count", 0, 1, static_cast<long long>(kMaxSweepCases)));
  } catch (const InputError& error) {
    throw InputError(file, "sample.count", error.message() + ": " + sweep_size_reason());
  }
  sample.seed = static_cast<std::uint64_t>(in.integer("seed", 0, 0, std::numeric_limits<long long>::max()));
  sample.method = in.choice("method", "latin_hypercube", {"latin_hypercube", "random"}) == "random"
                      ? SampleMethod::random
                      : SampleMethod::latin_hypercube;
  in.finish();
  return sample;
}

}  // namespace

SweepFile parse_sweep_file(const std::string& sweep_text, const std::string& path,
                           const std::optional<std::string>& base_text, const std::vector<std::string>& known_models) {
  const toml::table root = parse_scene_tree(sweep_text, path);
  for (const auto& [key, node] : root) {
    if (!kTopLevelKeys.contains(std::string(key.str()))) {
      throw InputError(path, std::string(key.str()),
                       "unknown key in a sweep file (allowed: name, description, base, run, [axes], [sample], [set])");
    }
  }
  SweepFile sweep;
  sweep.file = path;
  sweep.text = sweep_text;
  sweep.name = text_key(root, path, "name", fs::path(path).stem().string());
  sweep.description = text_key(root, path, "description", "");
  const std::string base = text_key(root, path, "base", "");
  if (base.empty()) throw InputError(path, "base", "is missing: the base scene file, relative to the sweep file");
  sweep.base_scene = (fs::path(path).parent_path() / base).lexically_normal().string();
  sweep.models = read_models(root, path, known_models);

  const toml::node* sample = root.get("sample");
  if (sample != nullptr && !sample->is_table()) throw InputError(path, "sample", "must be a [sample] table");
  if (sample != nullptr) sweep.sample = read_sample(*sample->as_table(), path);
  sweep.axes = read_axes(root, path, sweep.sample.has_value());
  std::set<std::string> names;
  for (const SweepAxis& axis : sweep.axes) {
    if (!names.insert(axis.name()).second) throw InputError(path, "axes." + axis.name(), "is given twice");
  }
  sweep.fixed = read_fixed(root, path);
  std::set<std::string> fixed_names;
  for (const SceneOverride& o : sweep.fixed) {
    const std::string name = o.section + "." + o.key;
    if (names.contains(name)) {
      throw InputError(path, "set." + name,
                       "is also an axis (axes." + name + "): a key is fixed in [set] or swept in [axes], not both");
    }
    if (!fixed_names.insert(name).second) throw InputError(path, "set." + name, "is given twice");
  }
  if (sweep.sample && std::none_of(sweep.axes.begin(), sweep.axes.end(), [](const SweepAxis& a) { return a.sampled; })) {
    throw InputError(path, "sample",
                     "has no range to sample: give at least one range without count, e.g. \"wheel.y\" = "
                     "{ from = 0.0, to = 0.019 }");
  }
  // The product, checked factor by factor so it cannot overflow.
  std::uint64_t cases = sweep.sample ? sweep.sample->count : 1;
  for (const SweepAxis& axis : sweep.axes) {
    if (axis.sampled) continue;
    if (cases > kMaxSweepCases / axis.values.size()) {
      throw InputError(path, "axes", "the grid has more than " + std::to_string(kMaxSweepCases) + " cases: " +
                                         sweep_size_reason());
    }
    cases *= axis.values.size();
  }
  if (sweep.sample) {
    const auto dimensions = static_cast<std::uint64_t>(
        std::count_if(sweep.axes.begin(), sweep.axes.end(), [](const SweepAxis& a) { return a.sampled; }));
    if (sweep.sample->count > kMaxSampleCoordinates / dimensions) {
      throw InputError(path, "sample.count",
                       "must be <= " + std::to_string(kMaxSampleCoordinates / dimensions) + " with " +
                           std::to_string(dimensions) + " sampled ranges: the points' coordinates are held in memory, "
                           "at most " + std::to_string(kMaxSampleCoordinates) + " (" +
                           std::to_string(kMaxSampleCoordinates * sizeof(double) >> 20) + " MB); got " +
                           std::to_string(sweep.sample->count));
    }
  }
  sweep.base_text = base_text ? *base_text : read_input_file(sweep.base_scene, "scene");
  return sweep;
}

SweepFile load_sweep_file(const std::string& path, const std::vector<std::string>& known_models) {
  return parse_sweep_file(read_input_file(path, "sweep"), path, std::nullopt, known_models);
}

}  // namespace railjoint
