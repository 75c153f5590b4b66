#include "sim/force_peaks.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace railjoint {

namespace {

// One pass of the bilinear-transform Butterworth (Direct Form I), started
// with the filter at rest on the first value. The pass filters the
// deviation from that value: at small steps (k = tan(pi f_c dt) ~ 1e-3) the
// recursion amplifies each step's round-off by 1 / (4 k^2), which on the
// whole force (P0 ~ 1e5 N) left a constant off by 2e-11; a constant's
// deviation is 0 exactly, and a pulse's error scales with the pulse.
void butterworth_pass(std::vector<double>& x, double step_s, double cutoff_Hz) {
  if (x.empty()) return;
  const double k = std::tan(std::numbers::pi * cutoff_Hz * step_s);
  const double norm = 1.0 / (1.0 + std::numbers::sqrt2 * k + k * k);
  const double b0 = k * k * norm;
  const double b1 = 2.0 * b0;
  const double b2 = b0;
  const double a1 = 2.0 * (k * k - 1.0) * norm;
  const double a2 = (1.0 - std::numbers::sqrt2 * k + k * k) * norm;
  const double rest = x.front();
  double x1 = 0.0, x2 = 0.0, y1 = 0.0, y2 = 0.0;
  for (double& value : x) {
    const double deviation = value - rest;
    const double y = b0 * deviation + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
    x2 = x1;
    x1 = deviation;
    y2 = y1;
    y1 = y;
    value = rest + y;
  }
}

}  // namespace

std::vector<double> zero_phase_lowpass(const std::vector<double>& force_N, double step_s, double cutoff_Hz) {
  std::vector<double> out = force_N;
  butterworth_pass(out, step_s, cutoff_Hz);
  std::reverse(out.begin(), out.end());
  butterworth_pass(out, step_s, cutoff_Hz);
  std::reverse(out.begin(), out.end());
  return out;
}

double lowpass_settling_s(double cutoff_Hz) {
  return std::log(1.0 / kLowpassEdgeDecay) / (2.0 * std::numbers::pi * cutoff_Hz / std::numbers::sqrt2);
}

LowPassedTop largest_in_window(std::span<const double> smooth, std::span<const double> time_s, double from_s,
                               double to_s) {
  LowPassedTop top;
  const std::size_t n = std::min(smooth.size(), time_s.size());
  std::size_t k = 0;
  while (k + 1 < n && time_s[k] < from_s) ++k;
  if (k >= n) return top;
  top = {k, smooth[k], time_s[k]};
  for (++k; k < n && time_s[k] <= to_s; ++k) {
    if (smooth[k] > top.force_N) top = {k, smooth[k], time_s[k]};
  }
  return top;
}

LowPassedTop lowpassed_top(const std::vector<double>& time_s, const std::vector<double>& force_N, double cutoff_Hz,
                           double from_s, double to_s) {
  if (time_s.size() < 3 || force_N.size() != time_s.size()) return {};
  const std::vector<double> smooth = zero_phase_lowpass(force_N, time_s[2] - time_s[1], cutoff_Hz);
  return largest_in_window(smooth, time_s, from_s, to_s);
}

ForcePeaks pick_force_peaks(const std::vector<double>& time_s, const std::vector<double>& force_N, double static_N,
                            double cutoff_Hz, double p2_mode_period_s) {
  ForcePeaks peaks;
  if (force_N.size() < 3 || time_s.size() != force_N.size()) return peaks;
  const std::vector<double> raw(force_N.begin() + 1, force_N.end());
  const std::size_t p1 = static_cast<std::size_t>(std::max_element(raw.begin(), raw.end()) - raw.begin());
  peaks.p1_N = raw[p1];
  peaks.p1_time_s = time_s[p1 + 1];
  if (p1 > 0 && p1 + 1 < raw.size()) {
    // The peak between the samples: the vertex of the parabola through the
    // largest and its neighbours (a fixed step).
    const double a = raw[p1 - 1], b = raw[p1], c = raw[p1 + 1];
    const double curvature = a - 2.0 * b + c;
    if (curvature < 0.0) {
      const double offset = 0.5 * (a - c) / curvature;
      peaks.p1_N = b - 0.25 * (a - c) * offset;
      peaks.p1_time_s += offset * (time_s[2] - time_s[1]);
    }
  }
  const double half = static_N + 0.5 * (peaks.p1_N - static_N);
  std::size_t first = p1;
  std::size_t last = p1;
  while (first > 0 && raw[first - 1] > half) --first;
  while (last + 1 < raw.size() && raw[last + 1] > half) ++last;
  peaks.p1_pulse_steps = 1.5 * static_cast<double>(last - first + 1);

  const double step_s = time_s[2] - time_s[1];
  const std::vector<double> smooth = zero_phase_lowpass(raw, step_s, cutoff_Hz);
  // The window: the P2 mode's first half period from the impact (the P1
  // pulse's start); the whole run without a mode.
  peaks.p2_window_end_s = p2_mode_period_s > 0.0 ? time_s[first + 1] + 0.5 * p2_mode_period_s : time_s.back();
  std::size_t end = smooth.size();  // one past the window's last sample
  while (end > 1 && time_s[end] > peaks.p2_window_end_s) --end;
  // The largest peak of the smoothed force after the P1 pulse; none there
  // (P1 and P2 merged into one hump): the smoothed force's largest in the
  // window (raw sample k is at time_s[k + 1]).
  std::size_t p2 = largest_in_window(smooth, std::span<const double>(time_s).subspan(1),
                                     -std::numeric_limits<double>::infinity(), peaks.p2_window_end_s)
                       .sample;
  bool after_p1 = false;
  for (std::size_t k = last + 1; k + 1 < end; ++k) {
    if (smooth[k] >= smooth[k - 1] && smooth[k] > smooth[k + 1] && (!after_p1 || smooth[k] > smooth[p2])) {
      p2 = k;
      after_p1 = true;
    }
  }
  peaks.p2_after_p1 = after_p1;
  peaks.p2_N = smooth[p2];
  peaks.p2_time_s = time_s[p2 + 1];
  // Flights after the impact: from the P1 pulse's start to the run's end.
  for (std::size_t k = first; k < raw.size();) {
    if (raw[k] > 0.0) {
      ++k;
      continue;
    }
    std::size_t after = k;
    while (after < raw.size() && !(raw[after] > 0.0)) ++after;
    // raw[k..after) is time_s[k + 1 .. after]; the flight began at time_s[k].
    const double length_s = time_s[after] - time_s[k];
    if (peaks.flights == 0) peaks.first_flight_s = time_s[k];
    ++peaks.flights;
    peaks.flight_time_s += length_s;
    peaks.longest_flight_s = std::max(peaks.longest_flight_s, length_s);
    k = after;
  }
  peaks.p2_across_flight = peaks.flights > 0 && peaks.first_flight_s < peaks.p2_time_s;
  peaks.p2_window_covered = time_s.back() >= peaks.p2_window_end_s &&
                            time_s.back() - peaks.p2_time_s >= lowpass_settling_s(cutoff_Hz);
  return peaks;
}

}  // namespace railjoint
