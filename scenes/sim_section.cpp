#include "scenes/sim_section.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "scenes/switched_keys.h"
#include "sim/force_setting_ranges.h"
#include "sim/setting_checks.h"
#include "support/input_error.h"

namespace railjoint {

namespace {

// One of `choices`, named as to_string names it.
template <class Choice>
Choice read_choice(SectionReader& in, const char* key, Choice fallback, std::initializer_list<Choice> choices) {
  std::vector<std::string_view> names;
  names.reserve(choices.size());
  for (const Choice choice : choices) names.emplace_back(to_string(choice));
  const std::string name = in.choice(key, to_string(fallback), names);
  for (const Choice choice : choices) {
    if (name == to_string(choice)) return choice;
  }
  return fallback;
}

// One key into its field (sim/setting_ranges.h), in its range; the mode is read apart.
void read_sim_key(SectionReader& in, const SimSettingKey& k) {
  const Range range = Range::of(k.range);
  if (double* const* number = std::get_if<double*>(&k.field)) {
    **number = in.number(k.key, **number, range);
  } else if (std::optional<double>* const* optional = std::get_if<std::optional<double>*>(&k.field)) {
    **optional = in.optional_number(k.key, range);
  } else if (int* const* count = std::get_if<int*>(&k.field)) {
    **count = static_cast<int>(in.integer(k.key, **count, static_cast<long long>(k.range.lo),
                                          static_cast<long long>(k.range.hi)));
  } else if (bool* const* flag = std::get_if<bool*>(&k.field)) {
    **flag = in.boolean(k.key, **flag);
  } else if (NarrowPhase* const* phase = std::get_if<NarrowPhase*>(&k.field)) {
    **phase = read_choice(in, k.key, **phase, {NarrowPhase::exact, NarrowPhase::bullet});
  } else if (HorizontalMotion* const* motion = std::get_if<HorizontalMotion*>(&k.field)) {
    **motion = read_choice(in, k.key, **motion, {HorizontalMotion::held, HorizontalMotion::free});
  }
}

// The rigid contact's keys that would change nothing in this combination: an error, not a silent no-op.
void check_rigid_contact_pairs(const SectionReader& in, const SimSettings& sim) {
  if (in.has("carrier_mass") && sim.inertial()->horizontal != HorizontalMotion::free) {
    throw InputError(
        in.file(), in.qualified("carrier_mass"),
        "only applies with inertial.horizontal = \"free\" (a held carrier keeps its speed whatever its mass)");
  }
  if (in.has("radius_of_gyration") && !(sim.friction > 0.0)) {
    throw InputError(in.file(), in.qualified("radius_of_gyration"),
                     "only applies with sim.friction > 0 (without friction nothing spins the wheel up or down)");
  }
}

// What sets the work of a force run on the discrete track: its nodes (the
// beam over the wheel's run each way and its decay length beyond) times its
// fixed steps over the approach and the run-out.
struct TrackRunWork {
  double approach_m = 0.0;
  double run_out_s = 0.0;
  double speed_m_per_s = 0.0;
  double time_step_s = 0.0;
  DiscreteTrackSettings track;

  double reach_m() const { return std::max(approach_m, run_out_s * speed_m_per_s); }
  double nodes() const { return static_cast<double>(discrete_track_nodes(track, reach_m())); }
  double steps() const { return (approach_m / speed_m_per_s + run_out_s) / time_step_s; }
  double node_steps() const { return nodes() * steps(); }
};

// A key that changes that work, in a TrackRunWork, with its range and the
// way that makes the run cheaper.
struct TrackWorkKey {
  const char* key;
  std::function<double&(TrackRunWork&)> value;
  SettingRange range;
  bool cheaper_up;
};

const std::vector<TrackWorkKey>& track_work_keys() {
  static const std::vector<TrackWorkKey> keys = {
      {"sim.force_time_step", [](TrackRunWork& w) -> double& { return w.time_step_s; }, sim_range::force_time_step,
       true},
      {"track.sleeper_spacing", [](TrackRunWork& w) -> double& { return w.track.sleeper_spacing_m; },
       track_range::sleeper_spacing, true},
      {"sim.approach_distance", [](TrackRunWork& w) -> double& { return w.approach_m; }, sim_range::approach_distance,
       false},
      {"sim.run_out_time", [](TrackRunWork& w) -> double& { return w.run_out_s; }, sim_range::run_out_time, false},
      {"track.bending_stiffness", [](TrackRunWork& w) -> double& { return w.track.bending_stiffness_N_m2; },
       track_range::bending_stiffness, false},
      {"track.pad_stiffness", [](TrackRunWork& w) -> double& { return w.track.support.pad_stiffness_N_per_m; },
       track_range::support_stiffness, true},
      {"track.ballast_stiffness", [](TrackRunWork& w) -> double& { return w.track.support.ballast_stiffness_N_per_m; },
       track_range::support_stiffness, true},
  };
  return keys;
}

// The value of one key, the others as they are, that brings the work
// within the budget, rounded to three figures on the side that fits; none
// when even the end of its range does not. The work falls monotonically
// that way (the node count in whole bays), so a bisection finds the edge.
std::optional<double> fitting_value(const TrackRunWork& work, const TrackWorkKey& k, double budget) {
  TrackRunWork trial = work;
  double& x = k.value(trial);
  const double as_given = x;
  // A longer step than the rail can follow is refused anyway (check_inertial_settings).
  const double longest_step_s = &x == &trial.time_step_s ? discrete_track_longest_step_s(work.track)
                                                                : std::numeric_limits<double>::infinity();
  const auto fits_at = [&](double value) {
    x = value;
    return k.range.contains(value) && value <= longest_step_s && trial.node_steps() <= budget;
  };
  // The end of the range that way, or just inside it where it is open.
  const bool open_end = k.cheaper_up ? k.range.hi_open : k.range.lo_open;
  const double end = k.cheaper_up ? k.range.hi : k.range.lo;
  double fits = std::min(open_end ? end + 1e-6 * (as_given - end) : end, longest_step_s);
  if (!fits_at(fits)) return std::nullopt;
  double too_big = as_given;
  for (int i = 0; i < 100; ++i) {
    const double middle = 0.5 * (fits + too_big);
    (fits_at(middle) ? fits : too_big) = middle;
  }
  const double unit = std::pow(10.0, std::floor(std::log10(std::abs(fits))) - 2.0);
  const double rounded = k.cheaper_up ? std::ceil(fits / unit) * unit : std::floor(fits / unit) * unit;
  return fits_at(rounded) ? rounded : fits;
}

std::string bound_text(const TrackWorkKey& k, double value) {
  std::string text = std::string(k.cheaper_up ? ">= " : "<= ") + setting_number(value);
  if (*k.range.unit) text.append(" ").append(k.range.unit);
  return text;
}

// The budget of a force run on the discrete track, blaming a key the user
// gave that would bring it within (a --set before the file's, then in
// track_work_keys' order), naming the others that would too.
void check_track_run_work(const Scene& scene, const TrackRunWork& work) {
  const double node_steps = work.node_steps();
  if (node_steps <= kMaxTrackNodeSteps) return;
  struct Fit {
    const TrackWorkKey* key;
    double value;
  };
  std::vector<Fit> given, defaults;
  for (const TrackWorkKey& k : track_work_keys()) {
    if (const std::optional<double> value = fitting_value(work, k, kMaxTrackNodeSteps)) {
      (scene.given(k.key) ? given : defaults).push_back({&k, *value});
    }
  }
  // The keys typed on the command line first, then the file's.
  std::stable_sort(given.begin(), given.end(),
                   [&](const Fit& a, const Fit& b) { return scene.origin(a.key->key) > scene.origin(b.key->key); });
  std::vector<Fit>& fits = given.empty() ? defaults : given;
  std::ostringstream why;
  why.precision(3);
  const double half_length_m = discrete_track_half_length_m(work.track, work.reach_m());
  why << "a force run on the discrete track may take at most " << kMaxTrackNodeSteps
      << " node-steps (its track nodes x its steps), here " << static_cast<long long>(work.nodes())
      << " nodes (every track.sleeper_spacing / " << work.track.nodes_per_bay << " over the wheel's "
      << work.reach_m() << " m each way and "
      << half_length_m - work.reach_m() << " m of beam beyond, 16 decay lengths on its supports) x "
      << static_cast<long long>(std::ceil(work.steps()))
      << " steps ((sim.approach_distance / wheel.speed + the run-out) / sim.force_time_step) = " << node_steps;
  if (fits.empty()) {
    throw InputError(scene.file, "sim.force_time_step",
                     "cannot be large enough alone: " + why.str() + "; shorten the run or coarsen the track");
  }
  std::string message = "must be " + bound_text(*fits.front().key, fits.front().value) + ": " + why.str();
  for (std::size_t i = 1; i < fits.size(); ++i) {
    message += (i == 1 ? "; or " : ", or ") + std::string(fits[i].key->key) + " " +
               bound_text(*fits[i].key, fits[i].value);
  }
  throw InputError(scene.file, fits.front().key->key, message);
}

}  // namespace

SimSettings read_sim_section(SectionReader& in, const KeyOrigins& origins) {
  SimSettings sim;
  for (const char* key : {"contact_stiffness", "contact_damping"}) {
    if (in.has(key)) {
      throw InputError(in.file(), in.qualified(key),
                       "has moved to the [contact] section: law = \"linear\" with stiffness [N/m] and damping "
                       "[N s/m] (or law = \"hertz\" for Hertz's contact)");
    }
  }
  if (read_choice(in, "mode", SimMode::kinematic, {SimMode::kinematic, SimMode::inertial}) == SimMode::inertial) {
    sim.make_inertial();
  }
  const std::vector<SimSettingKey> keys = sim_keys(sim);
  // An inertial run's keys are read before the contact law says which run
  // it is; a force run refuses those it does not read (force_sections.h).
  const unsigned runs = sim.inertial() ? kInertialRuns : kKinematicRun;
  std::vector<std::string_view> other_mode;
  other_mode.reserve(keys.size());
  for (const SimSettingKey& k : keys) {
    if ((k.runs & runs) == 0) other_mode.emplace_back(k.key);
  }
  if (sim.mode() == SimMode::kinematic) {
    refuse_keys_unless(in, origins, false, other_mode, "mode",
                       "only applies to mode = \"inertial\" (the kinematic mode holds the wheel's speed and "
                       "presses it onto the rail with sim.preload up to the impact, where it measures the jump)");
  } else {
    if (in.has("preload")) {
      throw InputError(in.file(), in.qualified("preload"),
                       "is the kinematic mode's press onto the rail; in mode = \"inertial\" the wheel is pressed "
                       "on by its weight and sim.wheel_load [N]");
    }
    in.expect(other_mode);  // a typo of one is named as such
  }
  for (const SimSettingKey& k : keys) {
    if ((k.runs & runs) == 0) continue;
    read_sim_key(in, k);
    if (std::string_view(k.key) == "horizontal") check_rigid_contact_pairs(in, sim);
  }
  in.finish();
  // The limits between two keys are sim/'s; here they name the key the user typed.
  try {
    check_setting_pairs(sim, origins);
  } catch (const InputError& error) {
    throw error.in_file(in.file());
  }
  return sim;
}

void check_sim_run_length(const Scene& scene) {
  const SimSettings& sim = scene.sim;
  const double v = scene.wheel.speed_m_per_s;
  // Travel before the impact (the inertial mode starts on its flat
  // approach) and the run-out after it. A run-out the simulation derives
  // from a predicted flight (inertial mode, none given) is not known here;
  // the rail it must end on bounds it (sim/crossing_model.h).
  const InertialSettings* inertial = sim.inertial();
  const double flat_approach_m = inertial ? inertial->flat_approach_m : 0.0;
  const ElasticCrossingSettings* elastic = inertial ? inertial->elastic() : nullptr;
  const double travel_m = sim.approach_distance_m + flat_approach_m;
  const double run_out_s = sim.run_out_time_s.value_or(elastic ? elastic->run_out_time_s : kDefaultRunOut_s);
  const double simulated_s = travel_m / v + run_out_s;
  if (elastic) {
    // A force run steps at its fixed step throughout.
    if (simulated_s / inertial->force_time_step_s <= kMaxSimSteps) {
      if (elastic->discrete_track) {
        check_track_run_work(scene, {sim.approach_distance_m, run_out_s, v, inertial->force_time_step_s,
                                     *elastic->discrete_track});
      }
      return;
    }
    throw InputError(scene.file, "sim.force_time_step",
                     "must be >= " + setting_seconds(simulated_s / kMaxSimSteps) +
                         ": a run may take at most 1e6 steps, and (sim.approach_distance" +
                         std::string(flat_approach_m > 0.0 ? " + sim.flat_approach" : "") +
                         ") / wheel.speed + the run-out is " + setting_seconds(simulated_s) + " of simulated time");
  }
  const double dt = sim.refined_time_step_s;
  if (simulated_s / dt <= kMaxSimSteps) return;

  const double budget_s = kMaxSimSteps * dt;  // simulated time the budget allows at the fine step
  const std::string why =
      "a run may take at most 1e6 steps (every step at sim.refined_time_step in the worst case): "
      "here (sim.approach_distance" +
      std::string(inertial ? " + sim.flat_approach" : "") +
      ") / wheel.speed + sim.run_out_time = " + setting_seconds(simulated_s) + " of simulated time";
  const auto refuse = [&](const std::string& key, const std::string& bound) {
    throw InputError(scene.file, key, "must be " + bound + ": " + why);
  };
  if (scene.given("sim.refined_time_step")) {
    refuse("sim.refined_time_step", ">= " + setting_seconds(simulated_s / kMaxSimSteps));
  }
  if (scene.given("sim.approach_distance") && budget_s > run_out_s) {
    refuse("sim.approach_distance", "<= " + metres_text((budget_s - run_out_s) * v - (travel_m - sim.approach_distance_m)));
  }
  if (scene.given("sim.flat_approach") && inertial && budget_s > run_out_s) {
    refuse("sim.flat_approach", "<= " + metres_text((budget_s - run_out_s) * v - sim.approach_distance_m));
  }
  if (scene.given("sim.run_out_time") && budget_s > travel_m / v) {
    refuse("sim.run_out_time", "<= " + setting_seconds(budget_s - travel_m / v));
  }
  if (scene.given("wheel.speed") && budget_s > run_out_s) {
    std::ostringstream bound;
    bound << ">= " << travel_m / (budget_s - run_out_s) << " m/s";
    refuse("wheel.speed", bound.str());
  }
  refuse("sim.refined_time_step", ">= " + setting_seconds(simulated_s / kMaxSimSteps));
}

}  // namespace railjoint
