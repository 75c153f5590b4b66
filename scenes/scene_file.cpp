#include "scenes/scene_file.h"
#include "scenes/scene_tree.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <sstream>

#include <toml++/toml.h>

#include "models/dip_profile.h"
#include "models/impact_prediction.h"
#include "models/parameter_checks.h"
#include "models/profile_curve.h"
#include "scenes/contact_patch_section.h"
#include "scenes/force_sections.h"
#include "scenes/input_file.h"
#include "scenes/profile_files.h"
#include "scenes/render_section.h"
#include "scenes/section_reader.h"
#include "scenes/sim_section.h"
#include "scenes/toml_limits.h"
#include "sim/crossing_model.h"
#include "support/input_error.h"

namespace railjoint {

namespace {

void build_checked_crossing(Scene& scene);  // below, beside the rail length it derives
void derive_simulated_rail_length(Scene& scene);

// The longest rail a scene gives or gets derived [m]: far beyond any track
// drawing, and it keeps the meshes' and the simulation's coordinates small.
constexpr double kMaxJointLength_m = 100.0;

// Sections a scene may have; each is read by the part of the program it switches on.
const std::set<std::string> kKnownSections = {"joint", "wheel", "sim", "contact", "track", "vehicle", "render",
                                              "contact_patch"};
const std::set<std::string> kKnownTopLevelKeys = {"name", "description"};

const toml::table* section_table(const toml::table& root, const std::string& file, const std::string& section) {
  const toml::node* node = root.get(section);
  if (node == nullptr) return nullptr;
  if (!node->is_table()) throw InputError(file, section, "must be a [" + section + "] table");
  return node->as_table();
}

void insert_override(toml::table& root, const std::string& file, const SceneOverride& assignment) {
  if (!root.contains(assignment.section)) root.insert(assignment.section, toml::table{});
  toml::table* target = root.get(assignment.section)->as_table();
  if (target == nullptr) {
    throw InputError(file, assignment.section, "is not a table, cannot set " + assignment.section + "." + assignment.key);
  }
  std::visit([&](const auto& value) { target->insert_or_assign(assignment.key, value); }, assignment.value);
}

// A top-level text key (name, description); a number there is an error, not
// a silently dropped value.
std::string top_level_text(const toml::table& root, const std::string& file, const char* key,
                           const std::function<std::string()>& fallback) {
  const toml::node* node = root.get(key);
  if (node == nullptr) return fallback();
  if (!node->is_string()) throw InputError(file, key, "must be a text in quotes, e.g. name = \"my joint\"");
  return node->value_or(std::string{});
}

// A measured profile file named by a scene key: the loader made its path
// absolute where it was typed (a relative one left is the scene file's), and
// `files` reads it once for every scene of the same source. Any fault is the
// key's, with the file's line.
std::shared_ptr<const ProfileCurve> read_measured_profile(SectionReader& in, const char* key, const std::string& name,
                                                          ProfileKind kind, ProfileFiles& files) {
  // Its noise: the RMS residual of the smoothing spline, 0 = through every point.
  const double tolerance_m = in.number("profile_tolerance", kDefaultProfileTolerance_m, Range::closed(0.0, 1e-4, "m"));
  const ProfileFile& file = files.get(profile_path_in(folder_of(in.file()), name), kind, tolerance_m);
  if (!file.curve) throw InputError(in.file(), in.qualified(key), file.error);
  return file.curve;
}

JointParams read_joint(SectionReader& in, ProfileFiles& files) {
  JointParams joint;
  const std::string kind = in.choice("kind", "inclined", {"inclined", "step"});
  joint.kind = kind == "step" ? JointKind::step : JointKind::inclined;
  const std::string dip_shape = in.choice("dip_shape", "linear", {"linear", "quadratic", "cosine"});
  joint.dip_shape = dip_shape == "quadratic" ? DipShape::quadratic
                    : dip_shape == "cosine"  ? DipShape::cosine
                                             : DipShape::linear;
  joint.theta_rad = in.degrees_as_radians("theta_deg", joint.theta_rad, Range::open_closed(0.0, 90.0, "deg"));
  // Upper bounds far beyond any track (a rail head 2 m wide, a rail 100 m
  // long) that keep the arithmetic finite; the model's own checks follow.
  joint.beta_rad = in.number("beta", joint.beta_rad, Range{0.0, 1.0, false, false, "rad"});
  joint.half_width_m = in.number("half_width", joint.half_width_m, Range::open_closed(0.0, 1.0, "m"));
  joint.length_m = in.number("length", joint.length_m, Range::open_closed(0.0, kMaxJointLength_m, "m"));
  joint.depth_m = in.number("depth", joint.depth_m, Range::open_closed(0.0, 1.0, "m"));
  joint.gap_m = in.number("gap", joint.gap_m, Range::closed(0.0, 1.0, "m"));
  joint.step_height_m = in.number("step_height", joint.step_height_m, Range::closed(-10.0, 10.0, "m"));
  // 0 is the thesis's flat head; a crown flatter than 100 m is flat to the
  // micrometre across any head, and the model asks for more than the head's
  // half-width (check_parameters).
  joint.crown_radius_m = in.number("crown_radius", joint.crown_radius_m, Range::closed(0.0, 100.0, "m"));
  // "crowned" when a crown radius is given, else "flat"; "60E1" brings its own radii.
  const std::string profile =
      in.choice("rail_profile", joint.crown_radius_m > 0.0 ? "crowned" : "flat", {"flat", "crowned", "60E1"}, ".csv");
  if (profile == "60E1") joint.rail_profile = RailProfile::en_60e1;
  if (profile.ends_with(".csv")) {
    joint.rail_profile = RailProfile::measured;
    joint.measured_head = read_measured_profile(in, "rail_profile", profile, ProfileKind::rail_head, files);
  } else if (in.has("profile_tolerance")) {
    throw InputError(in.file(), "joint.profile_tolerance", "applies to a measured rail_profile (a .csv file)");
  }
  if (profile == "crowned" && joint.crown_radius_m == 0.0) {
    throw InputError(in.file(), "joint.crown_radius", "must be given (> joint.half_width) with rail_profile = \"crowned\"");
  }
  if (profile == "flat" && joint.crown_radius_m > 0.0) {
    throw InputError(in.file(), "joint.rail_profile", "is \"flat\" but joint.crown_radius is " +
                                                          metres_text(joint.crown_radius_m) + ": use \"crowned\"");
  }
  joint.dip_length_m = in.number("dip_length", joint.dip_length_m, Range::open_closed(0.0, kMaxJointLength_m, "m"));
  // A dip as measured with a straight edge: its depth over dip_length each
  // side gives beta (models/dip_profile.h), up to the 1 rad beta allows.
  if (in.has("dip_depth")) {
    if (joint.dip_shape == DipShape::linear) {
      throw InputError(in.file(), "joint.dip_depth",
                       "applies to dip_shape = \"quadratic\" or \"cosine\"; the linear dip has no level, so no "
                       "depth: give joint.beta");
    }
    if (in.has("beta")) {
      throw InputError(in.file(), "joint.dip_depth",
                       "and joint.beta both give the dip's angle: give one (a cosine dip d deep over dip_length D "
                       "each side has beta = 2 atan(pi d / (2 D)), a quadratic one 2 atan(2 d / D))");
    }
    const double depth_m = in.number(
        "dip_depth", 0.0,
        Range::open_closed(0.0, dip_depth_m(joint.dip_shape, 1.0, joint.dip_length_m), "m"));
    joint.beta_rad = dip_angle_from_depth_rad(joint.dip_shape, depth_m, joint.dip_length_m);
  }
  in.finish();
  return joint;
}

WheelParams read_wheel(SectionReader& in, ProfileFiles& files) {
  WheelParams wheel;
  // Bounds far beyond any railway wheel that keep the arithmetic finite;
  // below 50 mm the default dip's 0.8 mm mismatch stops being small against R.
  wheel.radius_m = in.number("radius", wheel.radius_m, Range::closed(0.05, 10.0, "m"));
  // From 1 kg, the stability study's lightest.
  wheel.mass_kg = in.number("mass", wheel.mass_kg, Range::closed(1.0, 1e7, "kg"));
  wheel.width_m = in.number("width", wheel.width_m, Range::closed(0.0, 2.0, "m"));
  // On the widest rail head a scene takes (joint.half_width <= 1 m); the
  // model then asks |y| <= joint.half_width.
  wheel.lateral_m = in.number("y", wheel.lateral_m, Range::closed(-1.0, 1.0, "m"));
  // 0.1 m/s is walking pace; slower, a crossing takes seconds of simulated
  // time at microsecond steps.
  wheel.speed_m_per_s = in.number("speed", wheel.speed_m_per_s, Range::closed(0.1, 1000.0, "m/s"));
  // Treads are 1:40 (0.025) or 1:20 (0.05); a cone of 45 deg (1) is no tread.
  wheel.conicity = in.number("conicity", wheel.conicity, Range{-1.0, 1.0, true, true, {}});
  // A measured tread: (y, r) points, y from the wheel's plane; its r at
  // y = 0 is the rolling radius, so radius and conicity would say it twice.
  const std::string tread = in.text("profile", "");
  if (!tread.empty()) {
    for (const char* key : {"radius", "conicity"}) {
      if (in.has(key)) {
        throw InputError(in.file(), in.qualified(key), "is given by wheel.profile (" + tread + "): leave it out");
      }
    }
    wheel.measured_tread = read_measured_profile(in, "profile", tread, ProfileKind::wheel_tread, files);
    const ProfileCurve& curve = *wheel.measured_tread;
    if (!(curve.y_min_m() <= 0.0 && 0.0 <= curve.y_max_m())) {
      throw InputError(in.file(), in.qualified("profile"),
                       curve.source() + ": its y runs from " + metres_text(curve.y_min_m()) + " to " +
                           metres_text(curve.y_max_m()) + "; a tread must span y = 0, the wheel's plane, where its "
                           "r is the rolling radius (y is measured from the wheel's plane, in metres)");
    }
    wheel.radius_m = curve.value_m(0.0);
  } else if (in.has("profile_tolerance")) {
    throw InputError(in.file(), "wheel.profile_tolerance", "applies to a measured tread (wheel.profile, a .csv file)");
  }
  in.finish();
  return wheel;
}

// A joint key the joint's kind does not use changes nothing, so it is
// refused: given by --set (or a sweep's axis), or in a file that makes the
// kind itself. A shared base scene's inclined keys stay allowed when only
// the command line makes it a step.
void refuse_keys_the_joint_kind_ignores(const Scene& scene, const std::string& file,
                                        const std::vector<SceneOverride>& overrides) {
  const auto overridden = [&](const std::string& key) {
    return std::any_of(overrides.begin(), overrides.end(),
                       [&](const SceneOverride& o) { return o.section == "joint" && o.key == key; });
  };
  const bool step = scene.joint.kind == JointKind::step;
  const std::vector<std::string> ignored = step ? std::vector<std::string>{"theta_deg", "beta", "dip_shape", "dip_length", "dip_depth"}
                                                : std::vector<std::string>{"step_height"};
  // A dip length with the straight dip, which runs down the whole rail end.
  if (!step && scene.joint.dip_shape == DipShape::linear && scene.given("joint.dip_length")) {
    throw InputError(file, "joint.dip_length",
                     "applies to dip_shape = \"quadratic\" or \"cosine\"; the linear dip is straight over the whole "
                     "rail end");
  }
  for (const std::string& key : ignored) {
    if (!scene.given("joint." + key) || !(overridden(key) || !overridden("kind"))) continue;
    throw InputError(file, "joint." + key,
                     step ? "applies to kind = \"inclined\"; a step joint (kind = \"step\") is square and level on "
                            "each side, its one key is step_height"
                          : "applies to kind = \"step\"; an inclined joint has no step (its rail ends meet at the "
                            "bottom of its dip)");
  }
}

Scene read_scene(toml::table& root, const std::string& file, const std::vector<SceneOverride>& overrides,
                 SceneCheck check, bool record_keys, ProfileFiles& profiles) {
  for (const auto& assignment : overrides) insert_override(root, file, assignment);

  for (const auto& [key, node] : root) {
    const std::string name(key.str());
    if (node.is_table() ? !kKnownSections.contains(name) : !kKnownTopLevelKeys.contains(name)) {
      throw InputError(file, name, node.is_table() ? "unknown section" : "unknown top-level key");
    }
  }

  Scene scene;
  scene.file = file;
  for (const auto& [key, node] : root) {
    const std::string name(key.str());
    if (const toml::table* section = node.as_table()) {
      for (const auto& [section_key, value] : *section) scene.given_keys.insert(name + "." + std::string(section_key.str()));
    } else {
      scene.given_keys.insert(name);
    }
  }
  for (const SceneOverride& o : overrides) scene.command_line_keys.insert(o.section + "." + o.key);
  const KeyOrigins origins = [&scene](const std::string& key) { return scene.origin(key); };
  // The stem only when there is no name: a sweep reads a scene per case.
  scene.name = top_level_text(root, file, "name", [&] { return std::filesystem::path(file).stem().string(); });
  scene.description = top_level_text(root, file, "description", [] { return std::string(); });

  SectionReader joint(file, "joint", section_table(root, file, "joint"), record_keys);
  scene.joint = read_joint(joint, profiles);
  refuse_keys_the_joint_kind_ignores(scene, file, overrides);
  SectionReader wheel(file, "wheel", section_table(root, file, "wheel"), record_keys);
  scene.wheel = read_wheel(wheel, profiles);
  SectionReader sim(file, "sim", section_table(root, file, "sim"), record_keys);
  scene.sim = read_sim_section(sim, origins);
  SectionReader contact(file, "contact", section_table(root, file, "contact"), record_keys);
  SectionReader track(file, "track", section_table(root, file, "track"), record_keys);
  SectionReader vehicle(file, "vehicle", section_table(root, file, "vehicle"), record_keys);
  const HertzMaterial steels = read_force_sections(contact, track, vehicle, sim, scene.sim, origins);
  LinearContactSettings* spring = scene.sim.inertial() ? scene.sim.inertial()->linear_contact() : nullptr;
  if (spring && !scene.given("contact.damping")) {
    spring->damping_N_s_per_m = critical_contact_damping_N_s_per_m(spring->stiffness_N_per_m, scene.wheel.mass_kg);
  }
  check_sim_run_length(scene);
  if (record_keys) {
    for (SectionReader* reader : {&joint, &wheel, &sim, &contact, &track, &vehicle}) {
      scene.resolved.push_back(reader->take_resolved());
    }
  }
  if (const toml::table* render = section_table(root, file, "render")) {
    SectionReader render_reader(file, "render", render, record_keys);
    scene.render = read_render_section(render_reader);
    if (record_keys) scene.resolved.push_back(render_reader.take_resolved());
  }
  SectionReader contact_patch(file, "contact_patch", section_table(root, file, "contact_patch"), record_keys);
  scene.contact_patch = read_contact_patch_section(contact_patch, origins);
  scene.contact_patch.hertz.youngs_modulus_Pa = steels.youngs_modulus_Pa;
  scene.contact_patch.hertz.poisson_ratio = steels.poisson_ratio;
  scene.contact_patch.solved_contact.youngs_modulus_Pa = steels.youngs_modulus_Pa;
  scene.contact_patch.solved_contact.poisson_ratio = steels.poisson_ratio;
  if (record_keys) scene.resolved.push_back(contact_patch.take_resolved());

  // No joint.length given: the rails are as long as the model needs to carry
  // the wheel's contact on both sides (never shorter than the default 1 m,
  // never longer than the 100 m a scene may give). The analytic model needs
  // no rail length of its own (the thesis's section-3.2.2 example, a 0.3 m
  // step under a 1 m wheel, needs 1.55 m); the meshes' run-up is derived by
  // the mesh command, a simulation's approach and run-out below.
  if (check != SceneCheck::keys_only) derive_minimum_rail_length(scene);
  try {
    // The whole prediction, not only check_parameters: some limits (a gap the
    // wheel drops into) need the contact solve. It costs microseconds.
    if (check == SceneCheck::model || check == SceneCheck::simulation) {
      scene.prediction = predict_impact(scene.joint, scene.wheel);
      if (check == SceneCheck::simulation) {
        build_checked_crossing(scene);
      } else {
        derive_simulated_rail_length(scene);
      }
    } else if (check == SceneCheck::geometry) {
      check_parameters(scene.joint, scene.wheel);
    }
  } catch (const InputError& error) {
    throw error.in_file(file);
  }
  return scene;
}

// The recorded joint.length becomes the length derived for the run.
void record_derived_length(Scene& scene) {
  for (ResolvedSection& section : scene.resolved) {
    if (section.name != "joint") continue;
    for (ResolvedKey& key : section.keys) {
      if (key.key == "length") key = {key.key, scene.joint.length_m, KeySource::derived};
    }
  }
}

// A simulation's rails also carry its approach and run-out: in the inertial
// mode the run-out follows the predicted flight to its landing (2.4 m of
// rail on the default scene), in a force run past P2. A scene the
// simulation refuses (its wheel stand-in does not fit, say) keeps its
// length: the analytic model needs none, and the simulation reports the
// reason when it builds its model. `predictions`: the crossing's, when made.
double simulated_rail_length_m(const Scene& scene, const CrossingPredictions* predictions) {
  if (scene.given("joint.length")) return scene.joint.length_m;
  try {
    // The scene's own prediction, made once: only the stand-in wheel's is new.
    std::optional<CrossingPredictions> made;
    if (!predictions) {
      predictions = &made.emplace(
          predict_crossing(scene.joint, scene.wheel, scene.sim, scene.prediction ? &*scene.prediction : nullptr));
    }
    const double simulated_m = rail_length_needed_m(scene.joint, scene.wheel, scene.sim, *predictions);
    if (std::isfinite(simulated_m)) return std::clamp(simulated_m, scene.joint.length_m, kMaxJointLength_m);
  } catch (const InputError&) {
  }
  return scene.joint.length_m;
}

// The rails simulated_rail_length_m gives, recorded as derived.
void derive_simulated_rail_length(Scene& scene) {
  if (scene.given("joint.length")) return;
  scene.joint.length_m = simulated_rail_length_m(scene, nullptr);
  record_derived_length(scene);
}

// The scene's crossing into Scene::crossing, its rails recorded as derived.
void build_checked_crossing(Scene& scene) {
  double rail_length_m = 0.0;
  scene.crossing = scene_crossing(
      scene, *scene.prediction, [&scene](const std::string& key) { return scene.origin(key); }, rail_length_m);
  if (scene.given("joint.length")) return;
  scene.joint.length_m = rail_length_m;
  record_derived_length(scene);
}

}  // namespace

void derive_minimum_rail_length(Scene& scene) {
  if (scene.given("joint.length")) return;
  const double needed_m = minimum_joint_length_m(scene.joint, scene.wheel);
  if (std::isfinite(needed_m)) scene.joint.length_m = std::clamp(needed_m, scene.joint.length_m, kMaxJointLength_m);
  record_derived_length(scene);
}

std::shared_ptr<const CrossingModel> scene_crossing(const Scene& scene, const ImpactPrediction& prediction,
                                                    const KeyOrigins& origins, double& rail_length_m) {
  std::optional<CrossingPredictions> predictions;
  try {
    predictions = predict_crossing(scene.joint, scene.wheel, scene.sim, &prediction);
  } catch (const InputError&) {
  }
  const CrossingPredictions* made = predictions ? &*predictions : nullptr;
  JointParams joint = scene.joint;
  rail_length_m = joint.length_m = simulated_rail_length_m(scene, made);
  // The model's build checks the inputs again, as for settings built in code.
  check_simulation_inputs(joint, scene.wheel, scene.sim, origins);
  return std::make_shared<const CrossingModel>(build_crossing_model(joint, scene.wheel, scene.sim, made));
}

void check_for_simulation(Scene& scene) {
  derive_minimum_rail_length(scene);
  try {
    scene.prediction = predict_impact(scene.joint, scene.wheel);
    build_checked_crossing(scene);
  } catch (const InputError& error) {
    throw error.in_file(scene.file);
  }
}

bool is_scene_section(const std::string& name) { return kKnownSections.count(name) != 0; }

SceneOverride parse_override(const std::string& file, const std::string& assignment) {
  // A line break (a value pasted from a file, $'...' in a shell) would end the
  // TOML line that carries the value, and what follows it was dropped without
  // a word; no value holds a control character. A tab is layout, as below.
  if (std::any_of(assignment.begin(), assignment.end(),
                  [](unsigned char c) { return (c < 0x20 && c != '\t') || c == 0x7f; })) {
    throw InputError(file, assignment,
                     "--set takes one section.key=value without line breaks or other control characters; give each "
                     "key its own --set");
  }
  const auto equals = assignment.find('=');
  const auto dot = assignment.find('.');
  if (equals == std::string::npos || dot == std::string::npos || dot > equals) {
    throw InputError(file, assignment, "--set expects section.key=value, e.g. --set wheel.speed=30");
  }
  // Spaces around the names and the value are the user's layout, as in the
  // scene file (--set 'wheel.speed = 30'), not part of them.
  const auto trimmed = [](std::string text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return std::string();
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
  };
  const std::string section = trimmed(assignment.substr(0, dot));
  const std::string key = trimmed(assignment.substr(dot + 1, equals - dot - 1));
  const std::string value = trimmed(assignment.substr(equals + 1));
  if (section.empty() || key.empty()) throw InputError(file, assignment, "--set expects section.key=value");
  // A bare word with non-ASCII letters (--set name=Zürich) is text, as any
  // bare word is; toml++ must not see it (scenes/toml_limits.h).
  const bool bare = value.empty() || (value.front() != '"' && value.front() != '\'');
  if (bare && std::any_of(value.begin(), value.end(), [](char c) { return (static_cast<unsigned char>(c) & 0x80) != 0; })) {
    return {section, key, value};
  }

  try {
    const toml::table parsed = parse_toml("value = " + value, "--set", file, section + "." + key);
    const toml::node& node = *parsed.get("value");
    if (node.is_boolean()) return {section, key, node.as_boolean()->get()};
    if (node.is_integer()) return {section, key, static_cast<long long>(node.as_integer()->get())};
    if (node.is_floating_point()) return {section, key, node.as_floating_point()->get()};
    if (node.is_string()) return {section, key, node.as_string()->get()};
    throw InputError(file, section + "." + key, "--set takes a number, a text or true/false, got \"" + value + "\"");
  } catch (const toml::parse_error& error) {
    // A bare word (kind=step) is taken as a string; something that starts
    // like a number but does not parse (1e400, 0.5m) is an error, not a string.
    // A path (../head.csv, .\\tread.csv) is text: no number has a slash.
    const bool looks_numeric = !value.empty() && std::string("+-.0123456789").find(value.front()) != std::string::npos &&
                               value.find_first_of("/\\") == std::string::npos;
    // Numbers TOML is stricter about than a shell user (.005, +5., 050) are
    // taken when they read as one finite number end to end; without a point
    // or an exponent as an integer (an integer key takes 0100).
    const std::string digits = !value.empty() && value.front() == '+' ? value.substr(1) : value;
    const char* first = digits.data();
    const char* last = digits.data() + digits.size();
    long long whole = 0;
    double number = 0.0;
    const bool integral = digits.find_first_of(".eE") == std::string::npos;
    if (looks_numeric && integral && std::from_chars(first, last, whole).ptr == last) return {section, key, whole};
    if (const auto [end, status] = std::from_chars(first, last, number);
        looks_numeric && !integral && status == std::errc{} && end == last && std::isfinite(number)) {
      return {section, key, number};
    }
    // A number with a unit after it (120km/h, .005m) goes on as text: the
    // key's reader refuses it naming the unit the key takes, which only it knows.
    double prefix = 0.0;
    const auto [unit_start, prefix_status] = std::from_chars(first, last, prefix);
    if (looks_numeric && prefix_status == std::errc{} && unit_start != last &&
        std::isalpha(static_cast<unsigned char>(*unit_start))) {
      return {section, key, value};
    }
    if (looks_numeric) {
      throw InputError(file, section + "." + key,
                       "--set value \"" + value + "\" is not a valid number: " + std::string(error.description()));
    }
    return {section, key, value};
  }
}

toml::table parse_scene_tree(const std::string& toml_text, const std::string& name) {
  try {
    return parse_toml(toml_text, name, name, "");
  } catch (const toml::parse_error& error) {
    std::ostringstream where;
    where << "line " << error.source().begin.line << ", column " << error.source().begin.column;
    throw InputError(name, "", "not valid TOML (" + where.str() + "): " + std::string(error.description()));
  }
}

Scene read_scene_tree(const toml::table& root, const std::string& name, const std::vector<SceneOverride>& overrides,
                      SceneCheck check, ProfileFiles* profiles) {
  toml::table copy = root;
  if (profiles != nullptr) return read_scene(copy, name, overrides, check, false, *profiles);
  ProfileFiles own;
  return read_scene(copy, name, overrides, check, false, own);
}

ProfileSource profile_source_now(const std::string& name) {
  std::error_code ignored;
  return {folder_of(name), std::filesystem::current_path(ignored), std::make_shared<ProfileFiles>()};
}

namespace {

// --unset contact_patch.length: the key leaves the file's table, so it takes
// its default (or its derived value) as if the file never gave it.
void remove_key(toml::table& root, const std::string& file, const std::string& dotted) {
  const std::size_t dot = dotted.find('.');
  const std::string section = dot == std::string::npos ? "" : dotted.substr(0, dot);
  const std::string key = dot == std::string::npos ? "" : dotted.substr(dot + 1);
  if (section.empty() || key.empty()) {
    throw InputError(file, dotted, "--unset expects section.key, e.g. --unset contact_patch.length");
  }
  toml::table* table = root.get(section) != nullptr ? root.get(section)->as_table() : nullptr;
  if (table == nullptr || !table->contains(key)) {
    throw InputError(file, dotted, "--unset: the scene file does not give this key, so there is nothing to unset");
  }
  table->erase(key);
}

// The scene's tree with its unsets removed and its profile paths made
// absolute (the file's from its folder), and its overrides typed (theirs from
// the folder they were typed in).
toml::table anchored_tree(const std::string& toml_text, const std::string& name, const std::vector<std::string>& overrides,
                          const std::vector<std::string>& unsets, const ProfileSource& profiles,
                          std::vector<SceneOverride>& typed) {
  toml::table root = parse_scene_tree(toml_text, name);
  for (const std::string& key : unsets) remove_key(root, name, key);
  anchor_profile_paths(root, profiles.scene_folder);
  for (const std::string& assignment : overrides) {
    SceneOverride o = parse_override(name, assignment);
    if (const auto* text = std::get_if<std::string>(&o.value); text && names_profile_file(o.section, o.key, *text)) {
      o.value = profile_path_in(profiles.overrides_folder, *text);
    }
    typed.push_back(std::move(o));
  }
  return root;
}

}  // namespace

Scene parse_scene(const std::string& toml_text, const std::string& name, const std::vector<std::string>& overrides,
                  SceneCheck check, const std::vector<std::string>& unsets, const ProfileSource* profiles) {
  const ProfileSource source = profiles ? *profiles : profile_source_now(name);
  std::vector<SceneOverride> typed;
  toml::table root = anchored_tree(toml_text, name, overrides, unsets, source, typed);
  return read_scene(root, name, typed, check, true, *source.files);
}

toml::table scene_tree(const std::string& toml_text, const std::string& name,
                       const std::vector<std::string>& overrides, const std::vector<std::string>& unsets,
                       const ProfileSource* profiles) {
  std::vector<SceneOverride> typed;
  toml::table root = anchored_tree(toml_text, name, overrides, unsets, profiles ? *profiles : profile_source_now(name), typed);
  for (const SceneOverride& assignment : typed) insert_override(root, name, assignment);
  return root;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides, SceneCheck check,
                 const std::vector<std::string>& unsets) {
  return parse_scene(read_input_file(path, "scene"), path, overrides, check, unsets);
}

}  // namespace railjoint
