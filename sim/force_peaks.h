#pragma once
// P1 and P2 picked from a contact force history at a fixed step (a force
// run's). P1, the high-frequency peak of wheel and rail mass on the Hertz
// spring, is the largest raw force. P2, the low-frequency peak of wheel and
// track mass on the track's stiffness, is the largest peak of the force after
// a zero-phase low-pass filter (a second-order Butterworth run forwards and
// backwards, so no delay and a gain of 1 / (1 + (f / f_c)^4)) at f_c between
// the two (P2's 30-100 Hz pass, 2 % off at 0.4 f_c; P1's 0.3-2 kHz are
// smoothed out, 1/16 at 2 f_c) that comes after the P1 pulse (the raw force
// above half P1's height over the static load): on a discrete track P1 is
// broad and its smoothed hump would otherwise pass for P2. A history with no
// such later peak (one merged hump) gives the smoothed force's largest.
// Pure functions.

#include <vector>

namespace railjoint {

/// `force_N` sampled every `step_s` [s], filtered forwards and backwards by a
/// second-order Butterworth low-pass at `cutoff_Hz`, each pass started at
/// rest on its first value (a constant history passes unchanged).
std::vector<double> zero_phase_lowpass(const std::vector<double>& force_N, double step_s, double cutoff_Hz);

struct ForcePeaks {
  double p1_N = 0.0;
  double p1_time_s = 0.0;
  double p2_N = 0.0;
  double p2_time_s = 0.0;
  /// Steps across the P1 pulse: 1.5 x the samples above half its height over `static_N`.
  double p1_pulse_steps = 0.0;
  /// P2 is a peak of its own after the P1 pulse; false: one merged hump.
  bool p2_after_p1 = false;
};

/// P1 and P2 of the history at times `time_s` (a fixed step from the second
/// sample on; the first sample, before any step, carries no force and is left out).
ForcePeaks pick_force_peaks(const std::vector<double>& time_s, const std::vector<double>& force_N, double static_N,
                            double cutoff_Hz);

}  // namespace railjoint
