// Every output against its documentation (scenes/report/outputs.md): each
// command is run as a user runs it, and every JSON key and CSV column it
// writes must be in the Markdown table for that output, every documented one
// must be written by at least one of the runs, and every name with a unit
// must end in it.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.h"
#include "tests/support/scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using railjoint::testing_support::run_railjoint;
using railjoint::testing_support::scratch_path;

const std::string kSource = RAILJOINT_SOURCE_DIR;

/// Documented name -> unit, for one output.
using Table = std::map<std::string, std::string>;

/// The tables of outputs.md: a heading "### `<output>`" opens a table whose
/// rows are | `name` | unit | meaning |.
std::map<std::string, Table> read_schema() {
  std::ifstream in(kSource + "/scenes/report/outputs.md");
  std::map<std::string, Table> tables;
  Table* table = nullptr;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("#", 0) == 0) {
      const auto open = line.find('`');
      table = line.rfind("### ", 0) == 0 && open != std::string::npos
                  ? &tables[line.substr(open + 1, line.find('`', open + 1) - open - 1)]
                  : nullptr;
      continue;
    }
    if (table == nullptr || line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells;
    std::istringstream row(line.substr(1));
    for (std::string cell; std::getline(row, cell, '|');) {
      const auto first = cell.find_first_not_of(' ');
      cells.push_back(first == std::string::npos ? "" : cell.substr(first, cell.find_last_not_of(' ') - first + 1));
    }
    EXPECT_GE(cells.size(), 3u) << line;
    if (cells.size() < 3) continue;
    (*table)[cells[0].substr(1, cells[0].find('`', 1) - 1)] = cells[1];
  }
  return tables;
}

/// The keys of a JSON object: nested ones as "group.key", those of a list's
/// items as "list[].key"; a list and an empty object are keys themselves.
void flatten(const nlohmann::json& node, const std::string& prefix, std::set<std::string>& keys) {
  if (node.is_object() && !node.empty()) {
    for (const auto& [key, value] : node.items()) flatten(value, prefix.empty() ? key : prefix + "." + key, keys);
    return;
  }
  keys.insert(prefix);
  if (node.is_array()) {
    for (const auto& item : node) {
      if (item.is_object()) flatten(item, prefix + "[]", keys);
    }
  }
}

std::vector<std::string> csv_header(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> columns;
  std::istringstream cells(line);
  for (std::string cell; std::getline(cells, cell, ',');) columns.push_back(cell);
  return columns;
}

nlohmann::json run_json(const std::string& arguments) {
  const auto r = run_railjoint(arguments);
  EXPECT_EQ(r.exit_code, 0) << arguments << ": " << r.output;
  return nlohmann::json::parse(r.output);
}

// A name's unit: the suffix it must end in, "-" for none, "as ..." for keys
// named as the scene file names them.
void expect_unit_suffix(const std::string& output, const std::string& name, const std::string& unit) {
  if (unit == "-" || unit.rfind("as ", 0) == 0) return;
  const auto dot = name.find_last_of('.');
  const std::string last = dot == std::string::npos ? name : name.substr(dot + 1);
  EXPECT_TRUE(last.size() > unit.size() && last.compare(last.size() - unit.size() - 1, std::string::npos, "_" + unit) == 0)
      << output << ": " << name << " holds " << unit << " but does not end in _" << unit;
}

// `written`: the keys of every run of the output, together. `aliases`: a
// key under a prefix documented in another table under another prefix.
void expect_documented(const std::string& output, const std::set<std::string>& written, const Table& table,
                       const std::map<std::string, std::pair<const Table*, std::string>>& aliases = {}) {
  std::cout << output << ": " << written.size() << " keys written, " << table.size() << " documented\n";
  ASSERT_FALSE(table.empty()) << output << " has no table in outputs.md";
  for (const std::string& key : written) {
    bool found = table.contains(key);
    for (const auto& [prefix, target] : aliases) {
      if (!found && key.rfind(prefix, 0) == 0) found = target.first->contains(target.second + key.substr(prefix.size()));
    }
    EXPECT_TRUE(found) << output << " writes " << key << ", which outputs.md does not list";
  }
  for (const auto& [name, unit] : table) {
    expect_unit_suffix(output, name, unit);
    if (name.find('<') != std::string::npos) continue;  // a pattern (`<axis>`), checked by its caller
    bool present = false;
    for (const std::string& key : written) {
      present = present || key == name ||
                (key.rfind(name, 0) == 0 && (key[name.size()] == '.' || key[name.size()] == '['));
    }
    EXPECT_TRUE(present) << output << ": outputs.md lists " << name << ", which no run wrote";
  }
}

void expect_scene_block(const nlohmann::json& scene, const Table& table) {
  for (const char* key : {"file", "name", "description", "derived"}) {
    EXPECT_TRUE(scene.contains(key)) << key;
    EXPECT_TRUE(table.contains(key)) << key;
  }
  EXPECT_TRUE(table.contains("<section>.<key>"));
  for (const auto& [key, value] : scene.items()) {
    if (table.contains(key)) continue;
    ASSERT_TRUE(value.is_object()) << "scene." << key << " is neither documented nor a section";
    for (const auto& [name, setting] : value.items()) {
      EXPECT_TRUE(setting.is_primitive()) << "scene." << key << "." << name;
    }
  }
}

std::set<std::string> json_keys(const nlohmann::json& report, const Table& scene_table) {
  std::set<std::string> keys;
  flatten(report, "", keys);
  std::set<std::string> top;
  for (const std::string& key : keys) top.insert(key.rfind("scene.", 0) == 0 ? "scene" : key);
  expect_scene_block(report.at("scene"), scene_table);
  return top;
}

std::string write(const std::string& name, const std::string& text) {
  const fs::path path = scratch_path(name);
  std::ofstream(path) << text;
  return path.string();
}

const std::string kDefault = kSource + "/scenes/default.toml";

TEST(OutputSchema, AnalyticJsonCsvAndTopView) {
  const auto schema = read_schema();
  const std::string csv = scratch_path("schema_analytic.csv").string();
  const std::string top = scratch_path("schema_top_view.csv").string();
  const std::string section = scratch_path("schema_head_section.csv").string();
  const nlohmann::json j =
      run_json("analytic " + kDefault + " --json --csv " + csv + " --top-view " + top + " --head-section " + section);
  expect_documented("analytic --json", json_keys(j, schema.at("scene")), schema.at("analytic --json"));
  const auto columns = csv_header(csv);
  expect_documented("analytic --csv", {columns.begin(), columns.end()}, schema.at("analytic --csv"));
  const auto top_columns = csv_header(top);
  expect_documented("analytic --top-view", {top_columns.begin(), top_columns.end()}, schema.at("analytic --top-view"));
  const auto section_columns = csv_header(section);
  expect_documented("analytic --head-section", {section_columns.begin(), section_columns.end()},
                    schema.at("analytic --head-section"));
}

// Kinematic, inertial (rigid: flights; linear contact: the peak force) and force runs (one wheel, a bogie).
TEST(OutputSchema, SimulateJsonAndCsvInEveryMode) {
  const auto schema = read_schema();
  const std::string inertial = write("schema_inertial.toml",
                                     "[joint]\ntheta_deg = 30.0\nlength = 3.0\n[wheel]\ny = 0.015\nspeed = 50.0\n"
                                     "[sim]\nmode = \"inertial\"\nrun_out_time = 0.02\n");
  const std::vector<std::string> runs = {
      kDefault, inertial,
      inertial + " --set contact.law=linear --set contact.stiffness=1.5e9 --set sim.run_out_time=0.004",
      kSource + "/scenes/forces/lumped_track.toml", kSource + "/scenes/forces/bogie.toml"};
  std::set<std::string> keys;
  std::set<std::string> columns;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string csv = scratch_path("schema_simulate_" + std::to_string(i) + ".csv").string();
    const auto run_keys = json_keys(run_json("simulate " + runs[i] + " --json --csv " + csv), schema.at("scene"));
    keys.insert(run_keys.begin(), run_keys.end());
    const auto header = csv_header(csv);
    columns.insert(header.begin(), header.end());
  }
  const Table& analytic = schema.at("analytic --json");
  const Table& simulate = schema.at("simulate --json");
  expect_documented("simulate --json", keys, simulate,
                    {{"analytic.", {&analytic, ""}},
                     {"analytic_as_simulated.", {&analytic, ""}},
                     {"sim.flights[].", {&simulate, "sim.inertial.flights[]."}},
                     {"sim.phases[].", {&simulate, "sim.inertial.phases[]."}}});
  expect_documented("simulate --csv", columns, schema.at("simulate --csv"));
}

// Table 6.1's given patch, and a Hertz-sized one (its semi-axes).
TEST(OutputSchema, PressureJsonAndCsv) {
  const auto schema = read_schema();
  const std::string hertz = write("schema_hertz.toml", "[joint]\ngap = 0.006\n[contact_patch]\nsize = \"hertz\"\n");
  std::set<std::string> keys;
  std::set<std::string> columns;
  for (const std::string& scene : {kSource + "/scenes/pressure/table6_1.toml", hertz}) {
    const std::string csv = scratch_path("schema_pressure.csv").string();
    const auto run_keys = json_keys(run_json("pressure " + scene + " --json --csv " + csv), schema.at("scene"));
    keys.insert(run_keys.begin(), run_keys.end());
    const auto header = csv_header(csv);
    columns.insert(header.begin(), header.end());
  }
  expect_documented("pressure --json", keys, schema.at("pressure --json"));
  expect_documented("pressure --csv", columns, schema.at("pressure --csv"));
}

// The solved contact (elastic and capped, a static load and a force run's),
// on a coarse grid: every key and column documented. An elastic edge makes
// the run suspect (exit 1), its output written all the same.
TEST(OutputSchema, SolvedPressureJsonAndCsv) {
  const auto schema = read_schema();
  std::set<std::string> keys;
  std::set<std::string> columns;
  const std::string grid = " --set contact_patch.cells_x=64 --set contact_patch.cells_y=48 --set contact_patch.steps=5";
  for (const std::string& run : {"table6_1_solved.toml" + grid, "table6_1_solved.toml" + grid +
                                     " --set contact_patch.yield_pressure=1.15e9",
                                 "table6_1_solved_forces.toml" + grid}) {
    const std::string csv = scratch_path("schema_solved.csv").string();
    const auto r = run_railjoint("pressure " + kSource + "/scenes/pressure/" + run + " --json --csv " + csv);
    EXPECT_LE(r.exit_code, 1) << run << ": " << r.output;
    const auto run_keys = json_keys(nlohmann::json::parse(r.output.substr(0, r.output.find("\nrailjoint: "))),
                                    schema.at("scene"));
    keys.insert(run_keys.begin(), run_keys.end());
    const auto header = csv_header(csv);
    columns.insert(header.begin(), header.end());
  }
  expect_documented("solved pressure --json", keys, schema.at("solved pressure --json"));
  expect_documented("solved pressure --csv", columns, schema.at("solved pressure --csv"));
}

// One case through every model: the header holds every model's columns
// whether or not the case passes each (the pressure model refuses its gap).
TEST(OutputSchema, SweepResults) {
  const auto schema = read_schema();
  const std::string sweep = write("schema_sweep.toml", "name = \"schema\"\nbase = \"" + kSource +
                                                           "/scenes/forces/lumped_track.toml\"\n"
                                                           "run = [\"analytic\", \"simulate\", \"pressure\", \"forces\"]\n"
                                                           "[axes]\n\"wheel.speed\" = [40.0]\n");
  const fs::path out = scratch_path("schema_sweep_out");
  fs::remove_all(out);
  const auto r = run_railjoint("sweep " + sweep + " --out " + out.string() + " --jobs 1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::set<std::string> columns;
  for (const std::string& column : csv_header(out / "results.csv")) {
    columns.insert(column == "wheel.speed" ? "<axis>" : column);  // the axis, as the sweep file names it
  }
  const Table& table = schema.at("sweep results.csv");
  ASSERT_TRUE(table.contains("<axis>"));
  expect_documented("sweep results.csv", columns, table);
  EXPECT_TRUE(columns.contains("<axis>"));
}

}  // namespace
