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
// Both are looked for only in the P2 mode's first half period from the
// impact (the P1 pulse's start): a kick at the impact puts the mode's first
// crest at a quarter period or earlier (damping brings it forward), and what
// comes later (the next crest, a landing after a flight) is not P2. Without
// that window the pick was the largest peak of the whole run, so it depended
// on how long the run was (issue 41: a landing 26 ms in, 208 kN, replaced the
// merged hump's 376 kN once the run reached it).
// Pure functions.

#include <cstddef>
#include <limits>
#include <span>
#include <vector>

namespace railjoint {

/// `force_N` sampled every `step_s` [s], filtered forwards and backwards by a
/// second-order Butterworth low-pass at `cutoff_Hz`, each pass started at
/// rest on its first value (a constant history passes unchanged).
std::vector<double> zero_phase_lowpass(const std::vector<double>& force_N, double step_s, double cutoff_Hz);

/// A low-passed force's largest sample within a window.
struct LowPassedTop {
  std::size_t sample = 0;  ///< its index in the history given
  double force_N = 0.0;
  double time_s = 0.0;
};

/// The largest of `smooth` (a low-passed history at times `time_s`, the
/// same length) over the samples from the first at or after `from_s` to the
/// last at or before `to_s`, at least that first one; the earliest of equal
/// ones. The window P2 is picked in, written once for the contact's force
/// (pick_force_peaks) and a track support's (lowpassed_top).
LowPassedTop largest_in_window(std::span<const double> smooth, std::span<const double> time_s, double from_s,
                               double to_s);

/// A track support's P2: `force_N` through the zero-phase low pass at
/// `cutoff_Hz` (the step from the second and third samples), its largest in
/// [from_s, to_s]. A support's force is one hump as a wheel passes over it
/// (its own "P1 pulse" is the whole passage), so the contact's split into P1
/// and a later P2 does not carry over: the low-passed top within the
/// contact P2's window is its P2. Every sample counts, the first (the static
/// start) too.
LowPassedTop lowpassed_top(const std::vector<double>& time_s, const std::vector<double>& force_N, double cutoff_Hz,
                           double from_s = -std::numeric_limits<double>::infinity(),
                           double to_s = std::numeric_limits<double>::infinity());

struct ForcePeaks {
  double p1_N = 0.0;
  double p1_time_s = 0.0;
  double p2_N = 0.0;
  double p2_time_s = 0.0;
  /// Steps across the P1 pulse: 1.5 x the samples above half its height over `static_N`.
  double p1_pulse_steps = 0.0;
  /// P2 is a peak of its own after the P1 pulse; false: one merged hump.
  bool p2_after_p1 = false;
  /// Where P2 was looked for: up to the P1 pulse's start plus half the P2
  /// mode's period (the whole run without a mode) [s, the history's clock].
  double p2_window_end_s = 0.0;
  /// The run reached the window's end and ran on long enough after the P2
  /// peak for the filter's end transient to have decayed below
  /// kLowpassEdgeDecay of it: P2 does not depend on where the run ends.
  bool p2_window_covered = false;

  /// Contact lost after the impact (from the P1 pulse's start on): runs of
  /// samples whose force is 0 (Hertz's law gives exactly 0 off the rail).
  /// Sample k carries the force of the step that ends at time_s[k], so a run
  /// of n such samples is a flight of n steps, from the step before its first.
  int flights = 0;
  double flight_time_s = 0.0;     ///< all of them together
  double longest_flight_s = 0.0;
  double first_flight_s = 0.0;    ///< when the first one began (0: none)
  /// A flight began between the impact and P2: the low-passed force spans a
  /// time the wheel was off the rail, so P2 is no force the track carried
  /// through the mode (issue 41).
  bool p2_across_flight = false;
};

/// The backward pass starts at rest on the run's last value; the transient
/// that start leaves decays as exp(-zeta w_c t) (zeta = 1/sqrt 2 for a
/// second-order Butterworth). A P2 peak at least lowpass_settling_s(f_c)
/// before the end carries at most this fraction of the mismatch at the end.
inline constexpr double kLowpassEdgeDecay = 1e-3;

/// ln(1 / kLowpassEdgeDecay) / (w_c / sqrt 2): 10.4 ms at 150 Hz.
double lowpass_settling_s(double cutoff_Hz);

/// P1 and P2 of the history at times `time_s` (a fixed step from the second
/// sample on; the first sample, before any step, carries no force and is left out).
/// `p2_mode_period_s`: the period of wheel and track mass on K_T; 0 (no
/// track mode) looks for P2 over the whole run.
ForcePeaks pick_force_peaks(const std::vector<double>& time_s, const std::vector<double>& force_N, double static_N,
                            double cutoff_Hz, double p2_mode_period_s = 0.0);

}  // namespace railjoint
