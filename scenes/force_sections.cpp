#include "scenes/force_sections.h"

#include <algorithm>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "scenes/switched_keys.h"
#include "sim/force_setting_ranges.h"
#include "sim/setting_ranges.h"
#include "support/input_error.h"

namespace railjoint {

namespace {

// A section whose switch (contact.law, track.model, vehicle.model) picks a
// model, read by the table of its keys (sim/force_setting_ranges.h).
class SwitchedSection {
 public:
  SwitchedSection(SectionReader& in, const char* switch_key, std::initializer_list<std::string_view> values)
      : in_(in), switch_key_(switch_key), values_(values) {
    value_ = in.choice(switch_key, values_.front(), values_);
    model_ = static_cast<unsigned>(std::find(values_.begin(), values_.end(), value_) - values_.begin());
  }
  const std::string& value() const { return value_; }

  /// Refuses the keys no model chosen takes (switched_keys.h), a group of
  /// keys with the same models at a time, in `groups`' order.
  void refuse_other_models(const std::vector<ForceSettingKey>& keys, const KeyOrigins& origins,
                           std::initializer_list<unsigned> groups) {
    if (!in_.present()) return;  // no key to refuse, none to name
    for (const unsigned group : groups) {
      std::vector<std::string_view> names;
      names.reserve(keys.size());
      for (const ForceSettingKey& k : keys) {
        if (k.models == group) names.emplace_back(k.key);
      }
      const bool applies = (group & (1u << model_)) != 0;
      // The message only for a key it refuses: a sweep reads the section per case.
      std::string why;
      if (!applies && std::any_of(names.begin(), names.end(), [&](std::string_view key) { return in_.has(key); })) {
        std::string values;
        for (std::size_t i = 0; i < values_.size(); ++i) {
          if (group & (1u << i)) values.append(values.empty() ? "\"" : " or \"").append(values_[i]).append("\"");
        }
        why = "only applies with " + in_.qualified(switch_key_) + " = " + values;
      }
      refuse_keys_unless(in_, origins, applies, names, switch_key_, why);
    }
  }

  /// Reads the keys the chosen model takes, in the table's order; `check`
  /// runs once `check_after` is read (what it checks comes from the keys before).
  void read(const std::vector<ForceSettingKey>& keys, const char* check_after = "",
            const std::function<void()>& check = {}) {
    for (const ForceSettingKey& k : keys) {
      if ((k.models & (1u << model_)) == 0) continue;
      if (double* const* number = std::get_if<double*>(&k.field)) {
        **number = in_.number(k.key, **number, Range::of(k.range));
      } else if (int* const* count = std::get_if<int*>(&k.field)) {
        **count = static_cast<int>(in_.integer(k.key, **count, static_cast<long long>(k.range.lo),
                                               static_cast<long long>(k.range.hi)));
      } else {
        *std::get<std::optional<double>*>(k.field) = in_.optional_number(k.key, Range::of(k.range));
      }
      if (std::string_view(k.key) == check_after) check();
    }
  }

 private:
  SectionReader& in_;
  const char* switch_key_;
  std::vector<std::string_view> values_;
  std::string value_;
  unsigned model_ = 0;
};

// The [sim] keys a force run does not read (sim/setting_ranges.h: its mode,
// load and step, where it starts and ends, the thin disc's stand-in width
// and the contact's reach are all it reads): the rigid contact's switches,
// then Bullet's steps and solver as the section holds them, then the flat
// approach. A key added to [sim] is refused in a force run until it reads it.
void refuse_rigid_run_keys(const SectionReader& sim_in, const std::vector<SimSettingKey>& keys) {
  const auto read = [](const SimSettingKey& k) { return (k.runs & kForceRun) != 0; };
  // The force run holds the horizontal speed on a frictionless contact and
  // steps at its own fixed step with the exact narrow phase.
  for (const SimSettingKey& k : keys) {
    if (read(k) || k.part != SimKeyPart::rigid_contact || !sim_in.has(k.key)) continue;
    throw InputError(sim_in.file(), sim_in.qualified(k.key),
                     std::string("does not apply with contact.law = \"hertz\" (the force run holds the horizontal "
                                 "speed on a frictionless contact") +
                         (std::string_view(k.key) == "restitution" ? "; its dissipation is contact.restitution)" : ")"));
  }
  for (const std::string& key : sim_in.given_keys()) {
    const auto k = std::find_if(keys.begin(), keys.end(), [&](const SimSettingKey& x) { return key == x.key; });
    if (k != keys.end() && (read(*k) || k->part == SimKeyPart::flat_approach)) continue;
    throw InputError(sim_in.file(), sim_in.qualified(key),
                     "does not apply with contact.law = \"hertz\": the force run steps at sim.force_time_step "
                     "with the exact narrow phase and applies Hertz's force itself (Bullet solves no contact)");
  }
  // Its start is the static state on the incoming slope; the flat
  // approach's entry kink throws the wheel before the joint.
  for (const SimSettingKey& k : keys) {
    if (read(k) || k.part != SimKeyPart::flat_approach || !sim_in.has(k.key)) continue;
    throw InputError(sim_in.file(), sim_in.qualified(k.key),
                     "does not apply with contact.law = \"hertz\" (a force run starts in its static state on the "
                     "incoming slope, sim.approach_distance before the joint)");
  }
}

}  // namespace

HertzMaterial read_force_sections(SectionReader& contact_in, SectionReader& track_in, SectionReader& vehicle_in,
                                  SectionReader& sim_in, SimSettings& sim, const KeyOrigins& origins) {
  SwitchedSection contact(contact_in, "law", {"rigid", "linear", "hertz"});
  const std::string& law = contact.value();
  // The steels, one pair for the whole program (Hertz's elliptical constant
  // of a force run, the local model's Hertz patch), whatever the law.
  HertzMaterial material;
  material.youngs_modulus_Pa =
      contact_in.number("youngs_modulus", material.youngs_modulus_Pa, Range::of(contact_range::youngs_modulus));
  material.poisson_ratio =
      contact_in.number("poisson_ratio", material.poisson_ratio, Range::of(contact_range::poisson_ratio));
  SwitchedSection track(track_in, "model", {"rigid", "lumped", "discrete"});
  const std::string& track_model = track.value();
  SwitchedSection vehicle(vehicle_in, "model", {"load", "sprung", "bogie"});
  const std::string& vehicle_model = vehicle.value();

  // Each model's settings, filled by its keys (the linear law's damping,
  // left out, is critical for the scene's wheel: read_scene sets it).
  LinearContactSettings linear;
  std::optional<double> linear_damping;
  HertzContactSettings hertz;
  const std::vector<ForceSettingKey> contact_table = contact_keys(linear, linear_damping, hertz);
  LumpedTrackSettings lumped;
  DiscreteTrackSettings discrete;
  const std::vector<ForceSettingKey> track_table =
      track_keys(lumped, discrete, track_model == "lumped" ? lumped.support : discrete.support);
  PrimarySuspensionSettings sprung;
  BogieSettings bogie;
  const bool bogie_model = vehicle_model == "bogie";
  const std::vector<ForceSettingKey> vehicle_table = vehicle_keys(sprung, bogie, bogie_model);

  if (sim.mode() == SimMode::kinematic) {
    const char* const why = "only applies to sim.mode = \"inertial\" (the kinematic mode presses a rigid wheel "
                            "onto a rigid rail and measures the jump at the impact: no contact force, no track)";
    // A --set sim.mode=kinematic on a force scene is the mode's fault.
    const auto refuse = [&](const SectionReader& in, const std::string& key, const std::string& value) {
      if (origins("sim.mode") > origins(in.qualified(key))) {
        throw InputError(sim_in.file(), "sim.mode",
                         "must be \"inertial\" with " + in.qualified(key) + " = \"" + value + "\" (" +
                             origin_text(origins(in.qualified(key))) + "): the kinematic mode presses a rigid wheel "
                             "onto a rigid rail (no contact force, no track); leave sim.mode as the file has it");
      }
      throw InputError(in.file(), in.qualified(key), why);
    };
    if (law != "rigid") refuse(contact_in, "law", law);
    if (track_model != "rigid") refuse(track_in, "model", track_model);
    if (vehicle_model != "load") refuse(vehicle_in, "model", vehicle_model);
  }
  // Every key a section holds besides its switch only applies with that
  // switch set (switched_keys.h).
  contact.refuse_other_models(contact_table, origins, {kLinearLaw, kHertzLaw});
  track.refuse_other_models(track_table, origins, {kElasticTrack, kLumpedTrack, kDiscreteTrack});
  // The discrete track's rail: track.beam, and a Timoshenko rail's keys.
  TimoshenkoRailSettings timoshenko;
  const std::vector<ForceSettingKey> beam_table = timoshenko_keys(timoshenko);
  std::vector<std::string_view> beam_keys;
  beam_keys.reserve(1 + beam_table.size());
  beam_keys.emplace_back("beam");
  for (const ForceSettingKey& k : beam_table) beam_keys.emplace_back(k.key);
  refuse_keys_unless(track_in, origins, track_model == "discrete", beam_keys, "model",
                     "only applies with track.model = \"discrete\" (the rail beam's keys)");
  // Read (and echoed) only on the discrete track: no other has a rail beam.
  std::optional<SwitchedSection> beam;
  if (track_model == "discrete") {
    beam.emplace(track_in, "beam", std::initializer_list<std::string_view>{"euler", "timoshenko"});
    beam->refuse_other_models(beam_table, origins, {kTimoshenkoBeam});
  }
  vehicle.refuse_other_models(vehicle_table, origins, {kSprungVehicle, kSprungVehicle | kBogieVehicle, kBogieVehicle});
  // The bogie's wheels stand axle_spacing apart on one rail that rings
  // between them: the lumped track's one rail mass would put both on the
  // same spot, and a rigid track has nothing to pass from one to the other.
  if (bogie_model && law == "hertz" && track_model != "discrete") {
    // A --set track.model on a bogie scene is the track's fault.
    if (origins(track_in.qualified("model")) > origins(vehicle_in.qualified("model"))) {
      throw InputError(track_in.file(), track_in.qualified("model"),
                       "must be \"discrete\" with vehicle.model = \"bogie\" (got \"" + track_model +
                           "\"): the lumped track has one rail mass under both wheels, a rigid one no ringing to "
                           "pass from one to the other");
    }
    throw InputError(vehicle_in.file(), vehicle_in.qualified("model"),
                     "\"bogie\" needs track.model = \"discrete\" (got \"" + track_model +
                         "\"): its two wheels stand axle_spacing apart on a rail that carries the first one's "
                         "ringing to the second; the lumped track has one rail mass under both, a rigid one none");
  }
  if (law != "hertz") {
    const char* const why = "needs contact.law = \"hertz\" (forces on an elastic track and under a suspension follow "
                            "Hertz's contact law)";
    if (track_model != "rigid") throw InputError(track_in.file(), track_in.qualified("model"), why);
    if (vehicle_model != "load") throw InputError(vehicle_in.file(), vehicle_in.qualified("model"), why);
    if (sim_in.present()) {
      for (const SimSettingKey& k : sim_keys(sim)) {
        if (k.runs == kForceRun && sim_in.has(k.key)) {
          throw InputError(sim_in.file(), sim_in.qualified(k.key), "only applies with contact.law = \"hertz\"");
        }
      }
    }
  }

  // Past the check above, a contact law other than "rigid" is an inertial run's.
  contact.read(contact_table);
  if (law == "linear") {
    if (linear_damping) linear.damping_N_s_per_m = *linear_damping;
    sim.inertial()->contact = linear;
  }
  if (law == "hertz") {
    refuse_rigid_run_keys(sim_in, sim_keys(sim));
    ElasticCrossingSettings& elastic_run = sim.inertial()->contact.emplace<ElasticCrossingSettings>();
    elastic_run.contact = hertz;
    elastic_run.contact.youngs_modulus_Pa = material.youngs_modulus_Pa;
    elastic_run.contact.poisson_ratio = material.poisson_ratio;
    track.read(track_table);
    if (track_model == "lumped") elastic_run.track = lumped;
    if (track_model == "discrete") {
      beam->read(beam_table);
      if (beam->value() == "timoshenko") discrete.timoshenko = timoshenko;
      elastic_run.discrete_track = discrete;
    }
    const double wheel_load_N = sim.inertial()->wheel_load_N;
    if (vehicle_model == "sprung") {
      vehicle.read(vehicle_table, "sprung_mass", [&] {
        if (!sprung.sprung_mass_kg && !(wheel_load_N > 0.0)) {
          throw InputError(vehicle_in.file(), vehicle_in.qualified("model"),
                           "needs vehicle.sprung_mass [kg] when sim.wheel_load is 0 (the sprung mass defaults to "
                           "wheel_load / g)");
        }
      });
    }
    if (bogie_model) {
      vehicle.read(vehicle_table, "body_mass", [&] {
        if (!(bogie_body_mass_kg(bogie, wheel_load_N, kStandardGravity_m_per_s2) >= 1.0)) {
          throw InputError(vehicle_in.file(), vehicle_in.qualified("model"),
                           "needs vehicle.body_mass [kg] (1 to 1e6) when 2 sim.wheel_load / g does not exceed "
                           "vehicle.frame_mass by 1 kg (the body's share defaults to the rest of the two wheels' "
                           "loads)");
        }
      });
    }
    if (vehicle_model == "sprung") elastic_run.vehicle = sprung;
    if (bogie_model) elastic_run.bogie = bogie;
  }
  contact_in.finish();
  track_in.finish();
  vehicle_in.finish();
  return material;
}

}  // namespace railjoint
