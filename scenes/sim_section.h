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
/// if every step were refined. A fine step cost 4.5 us and 0.26 kB of
/// recorded trajectory here (default scene refined at 3e-9 s: 213,000 steps
/// in 0.96 s, +55 MB), so a run stays within about 5 s and 300 MB; the
/// slowest wheel (0.1 m/s) with the default steps needs 5e5.
inline constexpr double kMaxSimSteps = 1e6;

/// The most work a force run on the discrete track may take: its track nodes
/// times its steps (every step moves every node and sums its energy). A
/// node-step cost 4.6-6.2 ns here (1e9 of them 4.6 s of CPU, 3.8e9 23.7 s),
/// so a run stays within about 5 s, as kMaxSimSteps keeps the others.
inline constexpr double kMaxTrackNodeSteps = 1e9;

/// Throws InputError when the scene's run would take more than kMaxSimSteps
/// steps, or a force run on the discrete track more than kMaxTrackNodeSteps,
/// naming the key the user set (the fine step, the approach, the run-out,
/// the speed, the track's spacing and stiffnesses) and what would fit.
void check_sim_run_length(const Scene& scene);

}  // namespace railjoint
