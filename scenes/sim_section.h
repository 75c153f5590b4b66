#pragma once
// The [sim] section of a scene file: numerical and physical switches of the
// Bullet crossing scene (sim/sim_settings.h). Absent section: the defaults,
// which meet the accuracy target. Range-checked key by key here; the
// combinations (e.g. margin below the disc half width) are checked by
// sim/simulate_crossing.h when the run starts.

#include "scenes/scene.h"
#include "scenes/section_reader.h"
#include "sim/setting_checks.h"
#include "sim/sim_settings.h"

namespace railjoint {

/// Reads every key (range-checked) and the pairs of [sim] keys that must
/// agree (fine step below the coarse one, ...), blaming the key the user gave.
SimSettings read_sim_section(SectionReader& in, const KeyOrigins& origins);

/// The most steps a run may take: the simulated time over the fine step, as
/// if every step were refined. A run then stays within seconds and a few
/// hundred MB (docs/reliability.md, "Run length"); the slowest wheel
/// (0.1 m/s) with the default steps needs 5e5.
inline constexpr double kMaxSimSteps = 1e6;

/// The most work a force run on the discrete track may take: its track nodes
/// times its steps (every step moves every node and sums its energy): about
/// 5 s, as kMaxSimSteps keeps the others (docs/reliability.md, "Run length").
inline constexpr double kMaxTrackNodeSteps = 1e9;

/// Throws InputError when the scene's run would take more than kMaxSimSteps
/// steps, or a force run on the discrete track more than kMaxTrackNodeSteps,
/// naming the key the user set (the fine step, the approach, the run-out,
/// the speed, the track's spacing and stiffnesses) and what would fit.
void check_sim_run_length(const Scene& scene);

}  // namespace railjoint
