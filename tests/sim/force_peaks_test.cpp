// P1 and P2 from a force history (sim/force_peaks.h): the zero-phase
// low-pass against the gain of a second-order Butterworth run forwards and
// backwards, |H|^2 = 1 / (1 + (f / f_c)^4), and no delay; then both peaks
// picked from a synthetic history whose P1 and P2 are known in closed form.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "sim/force_peaks.h"

namespace railjoint {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStep_s = 2e-6;      // a force run's default step
constexpr double kCutoff_Hz = 150.0;  // between P2's 30-100 Hz and P1's 0.3-2 kHz

// A second-order Butterworth has |H(f)|^2 = 1 / (1 + (f / f_c)^4); forwards
// and backwards applies |H|^2 with no phase.
double forward_backward_gain(double frequency_Hz) { return 1.0 / (1.0 + std::pow(frequency_Hz / kCutoff_Hz, 4)); }

std::vector<double> sampled(std::size_t count, double step_s, double (*f)(double)) {
  std::vector<double> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = f(static_cast<double>(i) * step_s);
  return out;
}

// The largest |value| over the middle third of a filtered sine 0.5 s long:
// the start and end transients (each pass starts at rest) decay as
// exp(-2 pi f_c t / sqrt 2) = exp(-666 t), e^-110 at a third of the record.
double middle_amplitude(const std::vector<double>& y) {
  double amplitude = 0.0;
  for (std::size_t i = y.size() / 3; i < 2 * y.size() / 3; ++i) amplitude = std::max(amplitude, std::abs(y[i]));
  return amplitude;
}

// A constant passes unchanged. Filtered as a whole, it did not: at small
// steps (k = tan(pi f_c dt) = 9.42e-4 at 2e-6 s) the recursion amplifies each
// step's round-off by 1 / (4 k^2) = 2.8e5, which left 120 kN off by 1.2e-10
// relative. force_peaks.cpp filters the deviation from the first value,
// which for a constant is 0 exactly.
TEST(ZeroPhaseLowpass, AConstantPassesUnchanged) {
  const auto worst_change = [](double step_s, std::size_t count) {
    const std::vector<double> x(count, 120e3);
    const std::vector<double> y = zero_phase_lowpass(x, step_s, kCutoff_Hz);
    double worst = 0.0;
    for (const double value : y) worst = std::max(worst, std::abs(value / 120e3 - 1.0));
    return worst;
  };
  const double coarse = worst_change(1e-4, 401);    // 40 ms at 10 kHz: k = 0.047
  const double fine = worst_change(kStep_s, 20001);  // 40 ms at a force run's step
  const double finest = worst_change(1e-8, 40001);   // 0.4 ms at the smallest sim.force_time_step
  std::printf("constant 120 kN: worst relative change %.3g at 1e-4 s, %.3g at 2e-6 s, %.3g at 1e-8 s\n", coarse,
              fine, finest);
  // A constant's deviation is 0, and 0 stays 0: exact.
  EXPECT_EQ(coarse, 0.0);
  EXPECT_EQ(fine, 0.0);
  EXPECT_EQ(finest, 0.0);
}

TEST(ZeroPhaseLowpass, ASineInThePassBandKeepsTheButterworthGain) {
  // 0.2 f_c = 30 Hz, P2's band: gain 1 / (1 + 0.2^4) = 0.998403.
  const std::vector<double> x = sampled(250001, kStep_s, [](double t) { return std::sin(2.0 * kPi * 30.0 * t); });
  const double amplitude = middle_amplitude(zero_phase_lowpass(x, kStep_s, kCutoff_Hz));
  const double gain = forward_backward_gain(0.2 * kCutoff_Hz);
  std::printf("30 Hz sine: amplitude %.9f, Butterworth gain %.9f, difference %.3g\n", amplitude, gain,
              amplitude - gain);
  // The bilinear transform's warping at 30 Hz and 500 kHz sampling (~1e-7) and the sampled
  // crest (1 - cos(pi 30 Hz 2e-6 s) = 1.8e-8) stay far under 1e-5.
  EXPECT_NEAR(amplitude, gain, 1e-5);
}

TEST(ZeroPhaseLowpass, ASineFarAboveTheCutoffIsSmoothedOut) {
  // 10 f_c = 1.5 kHz, P1's band: gain 1 / (1 + 10^4) = 9.999e-5.
  const std::vector<double> x = sampled(250001, kStep_s, [](double t) { return std::sin(2.0 * kPi * 1500.0 * t); });
  const double amplitude = middle_amplitude(zero_phase_lowpass(x, kStep_s, kCutoff_Hz));
  const double gain = forward_backward_gain(10.0 * kCutoff_Hz);
  std::printf("1.5 kHz sine: amplitude %.6g, Butterworth gain %.6g\n", amplitude, gain);
  // The bilinear transform only lowers the gain above f_c (tan(pi f T) > pi f T); 1 % of the gain
  // (1e-6) leaves room for the round-off of the recursions.
  EXPECT_LT(amplitude, gain + 1e-6);
}

TEST(ZeroPhaseLowpass, NoDelay) {
  // A Gaussian bump of sigma 5 ms (its spectrum falls by e^-1/2 at 1 / (2 pi sigma) = 32 Hz)
  // at t = 50 ms in a 100 ms record: a filter with a delay would move its crest later.
  const double crest_s = 0.05;
  const std::size_t crest_index = static_cast<std::size_t>(std::lround(crest_s / kStep_s));
  const std::vector<double> x = sampled(50001, kStep_s, [](double t) {
    return 1e5 + 2e5 * std::exp(-0.5 * std::pow((t - 0.05) / 5e-3, 2));
  });
  const std::vector<double> y = zero_phase_lowpass(x, kStep_s, kCutoff_Hz);
  const std::size_t peak = static_cast<std::size_t>(std::max_element(y.begin(), y.end()) - y.begin());
  std::printf("Gaussian bump: crest at sample %zu, filtered peak at sample %zu (%.0f N against %.0f N)\n",
              crest_index, peak, y[peak], x[crest_index]);
  // Forwards and backwards is symmetric in time: the crest stays where it was, up to the sample grid.
  EXPECT_LE(peak > crest_index ? peak - crest_index : crest_index - peak, 1u);
}

// The synthetic history: a static 120 kN; P1 a half sine of +300 kN over
// 0.5 ms from t = 2 ms (crest at 2.25 ms); P2 a half sine of +100 kN at 30 Hz
// (half period 1/60 s = 16.67 ms) from t = 2 ms (crest at 2 + 8.33 ms).
constexpr double kStatic_N = 120e3;
constexpr double kStart_s = 2e-3;
constexpr double kP1Height_N = 300e3;
constexpr double kP1Width_s = 0.5e-3;
constexpr double kP2Height_N = 100e3;
constexpr double kP2Width_s = 1.0 / 60.0;

double p1_part_N(double t) {
  const double s = t - kStart_s;
  return s >= 0.0 && s <= kP1Width_s ? kP1Height_N * std::sin(kPi * s / kP1Width_s) : 0.0;
}
double p2_part_N(double t) {
  const double s = t - kStart_s;
  return s >= 0.0 && s <= kP2Width_s ? kP2Height_N * std::sin(kPi * s / kP2Width_s) : 0.0;
}
double history_N(double t) { return kStatic_N + p1_part_N(t) + p2_part_N(t); }

// Where history_N - level changes sign between a and b (bisection, to 1e-15 s).
double crossing_s(double a, double b, double level) {
  const bool rising = history_N(a) < level;
  for (int i = 0; i < 200 && b - a > 1e-15; ++i) {
    const double mid = 0.5 * (a + b);
    ((history_N(mid) < level) == rising ? a : b) = mid;
  }
  return 0.5 * (a + b);
}

TEST(PickForcePeaks, P1AndP2OfASyntheticHistory) {
  const std::size_t count = 20001;  // 0..40 ms at 2e-6 s
  std::vector<double> time_s(count), force_N(count);
  for (std::size_t i = 0; i < count; ++i) {
    time_s[i] = static_cast<double>(i) * kStep_s;
    force_N[i] = history_N(time_s[i]);
  }
  // A run's first sample, before any step, carries no force: it must be left out (a 0 here
  // would pull the filtered start, and so P2's filter, down by 120 kN).
  force_N[0] = 0.0;
  const ForcePeaks peaks = pick_force_peaks(time_s, force_N, kStatic_N, kCutoff_Hz);

  // P1: the P1 crest at 2.25 ms over the static load and P2 at that time,
  // 100 kN sin(pi 0.25 / 16.67) = 4.711 kN: 424.71 kN. P2's slope there
  // (1.88e7 N/s) against P1's curvature (-300 kN (pi / 0.5 ms)^2 = -1.18e13
  // N/s^2) moves the crest 1.6 us later and 15 N higher; the sample grid
  // misses a crest by at most (1 us)^2 x 1.18e13 / 2 = 6 N.
  const double p1_crest_s = kStart_s + 0.5 * kP1Width_s;
  const double p1_expected_N = kStatic_N + kP1Height_N + p2_part_N(p1_crest_s);
  std::printf("P1 %.1f N at %.6f ms; expected %.1f N at %.6f ms (%.1f N, %.2f steps off)\n", peaks.p1_N,
              peaks.p1_time_s * 1e3, p1_expected_N, p1_crest_s * 1e3, peaks.p1_N - p1_expected_N,
              (peaks.p1_time_s - p1_crest_s) / kStep_s);
  EXPECT_NEAR(peaks.p1_N, p1_expected_N, 0.005 * p1_expected_N);  // the brief's 0.5 %
  EXPECT_NEAR(peaks.p1_N, p1_expected_N, 50.0);  // at most 15 N + 6 N by hand (measured 14 N)
  // 1.6 us of slope shift plus at most half a step of grid: under 1.3 steps; 2 steps.
  EXPECT_NEAR(peaks.p1_time_s, p1_crest_s, 2.0 * kStep_s);

  // Steps across P1: 1.5 x the samples above half the height over the static load.
  // A bare half sine is above half its height while sin > 1/2, from 1/6 to 5/6 of
  // its width: 2/3 x 0.5 ms = 0.333 ms = 166.7 steps, 1.5 x = 250. P2 under the pulse
  // (1.6..7.9 kN) widens it: the crossings of the continuous history, by bisection.
  const double half_N = kStatic_N + 0.5 * (peaks.p1_N - kStatic_N);
  const double rise_s = crossing_s(kStart_s, p1_crest_s, half_N);
  const double fall_s = crossing_s(p1_crest_s, kStart_s + kP1Width_s, half_N);
  const double expected_steps = 1.5 * (fall_s - rise_s) / kStep_s;
  std::printf("P1 pulse: %.1f steps (1.5 x samples above %.1f N); continuous history %.3f to %.3f ms: %.2f steps; "
              "a bare half sine 250\n",
              peaks.p1_pulse_steps, half_N, rise_s * 1e3, fall_s * 1e3, expected_steps);
  // Samples in an interval are its width over the step rounded down or up: within 1 sample,
  // 1.5 steps, a hard bound rather than a margin (measured 1.3).
  EXPECT_NEAR(peaks.p1_pulse_steps, expected_steps, 1.5);
  // And near the bare half sine's 250: P2's 5 kN under a 300 kN pulse widens it by ~1 %; 3 % allowed.
  EXPECT_NEAR(peaks.p1_pulse_steps, 250.0, 0.03 * 250.0);

  // P2: 220 kN at the P2 crest, 2 + 8.33 ms, less what the filter takes:
  // - the filter's gain at 30 Hz, 1 / (1 + 0.2^4) = 0.998403, takes 160 N
  //   from an endless 30 Hz sine's crest (the zero-phase response's second
  //   moment is 0: only the 4th-order term remains); less from a half sine,
  //   whose ends are 0 where the sine would go negative;
  // - the filtered P1 pulse: its area 300 kN x 0.5 ms x 2/pi = 95.5 N s
  //   times the zero-phase impulse response, (w_c / (2 sqrt 2)) e^-a (cos a +
  //   sin a) with a = w_c t / sqrt 2 = 666.4/s x 8.08 ms = 5.39: 333.2/s x
  //   4.6e-3 x (0.624 - 0.781) = -0.24/s, so -23 N.
  // At most -0.18 kN in all, 0.08 % of 220 kN. (That impulse response
  // integrated numerically over the history, outside this code: -82 N - 24 N.)
  const double p2_crest_s = kStart_s + 0.5 * kP2Width_s;
  const double p2_nominal_N = kStatic_N + kP2Height_N;
  std::printf("P2 %.1f N at %.4f ms; nominal %.1f N at %.4f ms (%.1f N off, by hand -83 to -183 N; %.1f us late)\n",
              peaks.p2_N, peaks.p2_time_s * 1e3, p2_nominal_N, p2_crest_s * 1e3, peaks.p2_N - p2_nominal_N,
              (peaks.p2_time_s - p2_crest_s) * 1e6);
  EXPECT_NEAR(peaks.p2_N, p2_nominal_N, 0.03 * p2_nominal_N);  // the brief's 3 %
  // Measured -103 N, under the 183 N bound by hand: 1 kN (0.45 %) is ~10x above.
  EXPECT_NEAR(peaks.p2_N, p2_nominal_N, 1e3);
  // The P1 remnant's slope at the crest, area x dh/dt = 95.5 N s x 666.4/s x
  // 333.2/s x 4.6e-3 x (-2 sin a = 1.56) = 1.5e5 N/s, against P2's curvature
  // 100 kN (60 pi)^2 = 3.55e9 N/s^2 moves the crest 43 us later (the half sine
  // is symmetric about its crest and moves nothing); 1 ms is ~25x above.
  EXPECT_NEAR(peaks.p2_time_s, p2_crest_s, 1e-3);
  EXPECT_GT(peaks.p2_time_s, p2_crest_s);  // later, not earlier: the remnant is rising there
}

// P2 is looked for in the P2 mode's first half period after the impact
// only. The synthetic history above (P2 a 30 Hz half sine: a mode period of
// 1/30 s, its crest 8.33 ms after the P1 pulse's start) gets a second,
// larger hump (200 kN, 5 ms wide) 25 ms after the start, past the window's
// 16.7 ms, as a landing after a flight would give. The pick must not see it,
// and must see it with no mode period (the whole run).
TEST(PickForcePeaks, P2IsLookedForInTheModesFirstHalfPeriodOnly) {
  const std::size_t count = 25001;  // 0..50 ms at 2e-6 s
  constexpr double kLate_s = kStart_s + 25e-3, kLateWidth_s = 5e-3, kLate_N = 200e3;
  std::vector<double> time_s(count), force_N(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double t = static_cast<double>(i) * kStep_s;
    time_s[i] = t;
    force_N[i] = history_N(t) + (t >= kLate_s && t <= kLate_s + kLateWidth_s
                                     ? kLate_N * std::sin(kPi * (t - kLate_s) / kLateWidth_s)
                                     : 0.0);
  }
  force_N[0] = 0.0;
  const double period_s = 2.0 * kP2Width_s;  // a half sine of the mode is half its period
  const ForcePeaks windowed = pick_force_peaks(time_s, force_N, kStatic_N, kCutoff_Hz, period_s);
  const ForcePeaks whole = pick_force_peaks(time_s, force_N, kStatic_N, kCutoff_Hz);
  std::printf("window to %.3f ms: P2 %.1f N at %.3f ms; whole run: %.1f N at %.3f ms\n", windowed.p2_window_end_s * 1e3,
              windowed.p2_N, windowed.p2_time_s * 1e3, whole.p2_N, whole.p2_time_s * 1e3);
  // The window ends half a period after the P1 pulse's first sample above
  // half its height (1/6 of its 0.5 ms width after kStart_s), to a step.
  EXPECT_NEAR(windowed.p2_window_end_s, kStart_s + kP1Width_s / 6.0 + 0.5 * period_s, 2.0 * kStep_s);
  // The P2 crest as in P1AndP2OfASyntheticHistory (within 1 kN and 1 ms);
  // the late hump's low-passed tail adds nothing near it (e^-8 down, 17 ms off).
  EXPECT_NEAR(windowed.p2_N, kStatic_N + kP2Height_N, 1e3);
  EXPECT_NEAR(windowed.p2_time_s, kStart_s + 0.5 * kP2Width_s, 1e-3);
  EXPECT_TRUE(windowed.p2_after_p1);
  // 50 ms ends 31.7 ms after the crest, past the filter's 10.4 ms settling.
  EXPECT_TRUE(windowed.p2_window_covered);
  // Over the whole run the late hump (a 5 ms half sine is mostly below
  // 150 Hz: it keeps well over P2's 100 kN) is the largest.
  EXPECT_GT(whole.p2_time_s, kLate_s);
}

// Flights by hand: a history at 1e-5 s with P1 (a 0.5 ms, 300 kN half sine
// from 1 ms) and then the force 0 at samples 300-349 (50 steps, 0.5 ms) and
// 500-519 (20 steps, 0.2 ms), and one before the impact (samples 20-29),
// which is no flight after it. Sample k carries the step ending at k dt, so
// 50 zero samples are 50 steps off the rail, from (300 - 1) dt = 2.99 ms.
TEST(PickForcePeaks, FlightsAfterTheImpactCountedExactly) {
  constexpr double dt = 1e-5;
  const std::size_t count = 2001;  // 20 ms
  std::vector<double> time_s(count), force_N(count, kStatic_N);
  for (std::size_t i = 0; i < count; ++i) {
    time_s[i] = static_cast<double>(i) * dt;
    const double s = time_s[i] - 1e-3;
    if (s >= 0.0 && s <= 0.5e-3) force_N[i] += 300e3 * std::sin(kPi * s / 0.5e-3);
  }
  for (std::size_t i = 20; i < 30; ++i) force_N[i] = 0.0;
  for (std::size_t i = 300; i < 350; ++i) force_N[i] = 0.0;
  for (std::size_t i = 500; i < 520; ++i) force_N[i] = 0.0;
  force_N[0] = 0.0;
  // P2 at 1 ms + half of a 40 ms mode: the window reaches past both flights,
  // and P2 after them (the smoothed force recovers from the gaps) or before.
  const ForcePeaks peaks = pick_force_peaks(time_s, force_N, kStatic_N, kCutoff_Hz, 40e-3);
  std::printf("%d flights, %.6f ms in all, longest %.6f ms; P2 at %.3f ms, across a flight: %d\n", peaks.flights,
              peaks.flight_time_s * 1e3, peaks.longest_flight_s * 1e3, peaks.p2_time_s * 1e3,
              peaks.p2_across_flight ? 1 : 0);
  EXPECT_EQ(peaks.flights, 2);
  EXPECT_NEAR(peaks.flight_time_s, 70 * dt, 1e-15);
  EXPECT_NEAR(peaks.longest_flight_s, 50 * dt, 1e-15);
  EXPECT_NEAR(peaks.first_flight_s, 299 * dt, 1e-15);
  EXPECT_EQ(peaks.p2_across_flight, peaks.p2_time_s > 299 * dt);
}

// The window P2 is picked in (largest_in_window), on a made-up history whose
// answer is read off by eye: the bounds are inclusive, the earliest of equal
// values wins, and a window past the history's end keeps its first sample
// (a history that ends before the window opens has no other to give).
TEST(LargestInWindow, BoundsAreInclusiveAndTheEarliestOfEqualsWins) {
  const std::vector<double> t{0.0, 1.0, 2.0, 3.0, 4.0, 5.0};
  const std::vector<double> f{9.0, 1.0, 5.0, 5.0, 2.0, 8.0};
  const auto top = [&](double from_s, double to_s) { return largest_in_window(f, t, from_s, to_s); };
  EXPECT_EQ(top(-INFINITY, INFINITY).sample, 0u);
  EXPECT_EQ(top(1.0, 4.0).sample, 2u);  // 5 at t = 2 and 3: the earlier
  EXPECT_EQ(top(1.0, 4.0).time_s, 2.0);
  EXPECT_EQ(top(3.0, 5.0).sample, 5u);  // both ends inclusive
  EXPECT_EQ(top(3.0, 4.9).force_N, 5.0);
  EXPECT_EQ(top(0.5, 0.7).sample, 1u);  // nothing inside: the first at or after from_s
  EXPECT_EQ(top(7.0, 9.0).sample, 5u);  // past the end: the last sample
}

// A support's P2 (lowpassed_top) on a constant history is that constant (the
// filter passes a constant unchanged, ZeroPhaseLowpass above), wherever the
// window lies.
TEST(LowpassedTop, AConstantSupportForceIsItsOwnP2) {
  std::vector<double> t, f;
  for (int k = 0; k < 200; ++k) {
    t.push_back(k / 8192.0);  // exact in binary: the window's bounds land on samples
    f.push_back(39.5e3);
  }
  EXPECT_EQ(lowpassed_top(t, f, 150.0).force_N, 39.5e3);
  EXPECT_EQ(lowpassed_top(t, f, 150.0, 50 / 8192.0, 60 / 8192.0).force_N, 39.5e3);
  EXPECT_EQ(lowpassed_top(t, f, 150.0, 50 / 8192.0, 60 / 8192.0).sample, 50u);
}

}  // namespace
}  // namespace railjoint
