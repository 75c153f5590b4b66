#pragma once
// Checks of the [sim] keys and of the combinations the scene reader's
// ranges cannot see, for both modes: one InputError naming "sim.<key>"
// (or the joint or wheel key to blame) and the allowed range. Also the wheel
// as simulated, which several checks depend on.

#include <functional>
#include <sstream>
#include <string>

#include "models/parameters.h"
#include "sim/force_setting_ranges.h"
#include "sim/setting_ranges.h"
#include "sim/sim_settings.h"
#include "support/input_error.h"

namespace railjoint {

/// A number as the user would type it (shortest round-trip is not needed
/// here; 0, never "-0": -sim.slop with a slop of 0).
inline std::string setting_number(double value) {
  std::ostringstream out;
  out << value + 0.0;
  return out.str();
}

/// "2e-06 s", as setting_number gives the number.
inline std::string setting_seconds(double value_s) { return setting_number(value_s) + " s"; }

/// Where a scene key's value came from. When two keys disagree the error
/// blames the one the user typed last: the command line (--set, a sweep's
/// axis) over the scene file over a default. Settings built in code come
/// from nowhere: every key is a default_value, and the first key of a pair
/// takes the blame.
enum class KeyOrigin { default_value, file, command_line };
/// The origin of a key, "section.key" ("sim.margin", "wheel.width").
using KeyOrigins = std::function<KeyOrigin(const std::string& key)>;
/// No key typed: settings built in code.
inline KeyOrigin no_key_given(const std::string& /*key*/) { return KeyOrigin::default_value; }

/// "in the file", "from --set", "the default": where `key` came from, for a
/// message that names the key it conflicts with.
inline std::string origin_text(KeyOrigin origin) {
  return origin == KeyOrigin::command_line ? "from --set" : origin == KeyOrigin::file ? "in the file" : "the default";
}

inline void require_setting(bool ok, const std::string& key, const std::string& message) {
  if (!ok) throw InputError("sim." + key, message);
}

/// A key's own range (setting_ranges.h, force_setting_ranges.h) for a
/// setting built in code: "must be in [lo, hi] unit, got x", naming the
/// key as a scene writes it ("track.pad_stiffness").
inline void require_key_in_range(double value, const std::string& qualified_key, const SettingRange& range) {
  if (range.contains(value)) return;
  std::string text = std::string("must be in ") + (range.lo_open ? "(" : "[") + setting_number(range.lo) + ", " +
                     setting_number(range.hi) + (range.hi_open ? ")" : "]");
  if (*range.unit) text.append(" ").append(range.unit);
  throw InputError(qualified_key, text + ", got " + setting_number(value));
}

/// require_key_in_range for a [sim] key ("time_step").
inline void require_in_range(double value, const std::string& key, const SettingRange& range) {
  require_key_in_range(value, "sim." + key, range);
}

/// The limits between two [sim] settings that no range of one can see:
/// sim.refined_time_step <= sim.time_step, sim.refine_distance <
/// sim.contact_breaking_threshold, sim.contact_processing_threshold >
/// -sim.slop. Owned here, for settings built in code and read from a scene
/// alike: throws InputError naming the key the user typed last (KeyOrigin;
/// the first of the pair on a tie), with a message that names the other.
void check_setting_pairs(const SimSettings& settings, const KeyOrigins& origins);

/// The wheel as simulated: a thin disc (width 0) becomes a cylinder of width
/// 2 sim.disc_half_width (Bullet has no zero-width shape) whose inner face
/// lies in the disc's plane: it reaches away from the centre line,
/// y in [y_w, y_w + 2h] for y_w > 0 (mirrored for y_w < 0). Why that makes
/// it strike as the disc does: its jump depends only on the incoming rail's
/// farthest end and the outgoing rail's nearest start under it
/// (tests/sim/exact_jump_reference.h), and with the cut running forward as
/// |y| grows, the slice that governs a strike on the step-up side
/// (outgoing start) and the landing on the step-down side (incoming end) is
/// the inner face, at y_w. On the V (scenario 1) both rails are met by their
/// planes, which any slice sees alike (sim/DESIGN.md: a centred cylinder
/// strikes below the disc).
inline WheelParams wheel_as_simulated(const WheelParams& wheel, const SimSettings& settings) {
  WheelParams simulated = wheel;
  if (simulated.width_m == 0.0) {
    const double h = settings.disc_half_width_m;
    simulated.width_m = 2.0 * h;
    if (wheel.lateral_m > 0.0) simulated.lateral_m += h;
    if (wheel.lateral_m < 0.0) simulated.lateral_m -= h;
  }
  return simulated;
}

/// The wheel a simulation runs: a thin disc's stand-in cylinder
/// (wheel_as_simulated) where the rails are meshes, the wheel itself where
/// the narrow phase reads the analytic tops (runs_on_analytic_rail_tops,
/// sim/rail_surface.h), which take a disc as it is; Bullet's shape for it is
/// then only the broadphase's.
WheelParams simulated_wheel_of(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings);

/// The nodes of the discrete track (sim/discrete_track.h) a force run steps
/// when its wheel runs `run_reach_m` each way from the joint: every
/// track.sleeper_spacing / track.nodes_per_bay over that reach and the beam's own decay length
/// beyond it (6 / beta_f, from the bending and support stiffnesses).
std::size_t discrete_track_nodes(const DiscreteTrackSettings& track, double run_reach_m);
/// The half length of that track [m].
double discrete_track_half_length_m(const DiscreteTrackSettings& track, double run_reach_m);
/// The largest sim.force_time_step that track's rail can follow: 1 / omega
/// of its stiffest bending mode [s] (check_inertial_settings).
double discrete_track_longest_step_s(const DiscreteTrackSettings& track);

/// The inertial-only settings and their combinations; a discrete track's
/// grid against the step blames the key the user typed last (`origins`).
void check_inertial_settings(const SimSettings& settings, const JointParams& joint, const WheelParams& wheel,
                             const KeyOrigins& origins = no_key_given);

/// Checks the settings and the combinations the [sim] range checks cannot
/// see (margin below the disc half width, run inside the rail ends, ...);
/// a combination of a [sim] key and a joint or wheel key blames the one the
/// user typed last (`origins`).
void check_sim_settings(const SimSettings& settings, const JointParams& joint, const WheelParams& wheel,
                        const KeyOrigins& origins = no_key_given);

/// Everything a simulation checks before it builds a world, in the order
/// that blames the right key: the joint and wheel (check_joint_geometry), a
/// jump to measure (no level joint), then the settings.
void check_simulation_inputs(const JointParams& joint, const WheelParams& wheel, const SimSettings& settings,
                             const KeyOrigins& origins = no_key_given);

}  // namespace railjoint
