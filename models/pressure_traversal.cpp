#include "models/pressure_traversal.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>

#include <boost/math/tools/minima.hpp>

#include "models/hertz_contact.h"
#include "models/patch_gap_overlap.h"
#include "support/input_error.h"

namespace railjoint {

namespace {

// Brent's method to about 1e-9 of the bracket (the extrema are smooth maxima
// of smooth functions; a flat top, as a rectangle's, is found anywhere on it).
constexpr int kBrentBits = 30;

template <class F>
double argmax_between(F f, double lo, double hi) {
  std::uintmax_t iterations = 200;
  return boost::math::tools::brent_find_minima([&f](double x) { return -f(x); }, lo, hi, kBrentBits, iterations).first;
}

// The sample index with the largest f, and its neighbours as a bracket.
template <class F>
std::pair<double, double> bracket_of_best_sample(const std::vector<PressureState>& samples, F f) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    if (f(samples[i]) > f(samples[best])) best = i;
  }
  const std::size_t lo = best == 0 ? 0 : best - 1;
  const std::size_t hi = std::min(best + 1, samples.size() - 1);
  return {samples[lo].x_front_m, samples[hi].x_front_m};
}

PointOfInterest point(int number, const char* what, const PressureState& state) { return {number, what, state}; }

}  // namespace

void check_pressure_inputs(const PressureInputs& inputs) {
  if (!(inputs.gap.gap_m > 0.0)) {
    throw InputError("joint.gap",
                         "must be > 0 for the contact-pressure model: with no end-post gap the patch never leaves the "
                         "rail and the pressure stays P0 (table 6.1 uses 0.006 m)");
  }
  const PatchSpan span = patch_span_m(inputs.patch, cut_normal(inputs.gap));
  const double across_m = span.max_m - span.min_m;
  if (!(inputs.gap.gap_m < across_m)) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "must be narrower than the patch across the cut (%s at theta = %.4g deg): a wider gap leaves no "
                  "bearing area and the pressure is unbounded",
                  metres_text(across_m).c_str(), inputs.gap.theta_rad * 180.0 / std::numbers::pi);
    throw InputError("joint.gap", text);
  }
}

double traversal_end_m(const PressureInputs& inputs) {
  const auto corners = gap_parallelogram_m(inputs.gap, inputs.patch.width_m);
  return corners[2].x() + inputs.patch.length_m;  // P_br.x + a
}

PressureState pressure_state(const PressureInputs& inputs, double x_front_m) {
  const GapOverlap overlap = patch_gap_overlap(inputs.patch, inputs.gap, x_front_m);
  PressureState state;
  state.x_front_m = x_front_m;
  state.reduction_area_m2 = overlap.area_m2;
  state.active_area_m2 = patch_area_m2(inputs.patch) - overlap.area_m2;
  state.pressure_Pa = inputs.normal_force_N / state.active_area_m2;
  state.rate_Pa_per_m = inputs.normal_force_N * overlap.d_area_d_x_front_m / (state.active_area_m2 * state.active_area_m2);
  return state;
}

std::vector<PressureState> pressure_traversal(const PressureInputs& inputs) {
  const double x_end = traversal_end_m(inputs);
  std::vector<PressureState> states;
  states.reserve(static_cast<std::size_t>(inputs.steps));
  // numpy.linspace(0, x_end, steps), as the thesis's get_xs.
  for (int i = 0; i < inputs.steps; ++i) {
    const double x = (i == inputs.steps - 1) ? x_end : x_end * i / (inputs.steps - 1);
    states.push_back(pressure_state(inputs, x));
  }
  return states;
}

double PressureSummary::max_abs_rate_Pa_per_s(double speed_m_per_s) const {
  return speed_m_per_s * std::max(at_max_rate.rate_Pa_per_m, -at_min_rate.rate_Pa_per_m);
}

PressureSummary summarize_pressure(const PressureInputs& inputs, const std::vector<PressureState>& traversal) {
  PressureSummary s;
  s.initial_area_m2 = patch_area_m2(inputs.patch);
  s.p0_Pa = inputs.normal_force_N / s.initial_area_m2;
  s.g_long_m = longitudinal_gap_m(inputs.gap);
  s.x_end_m = traversal_end_m(inputs);

  // Where the patch meets the two cut lines n.p = 0 and n.p = g: the patch at
  // x_front spans [min + sin(theta) x_front, max + sin(theta) x_front] along n.
  const Eigen::Vector2d n = cut_normal(inputs.gap);
  const PatchSpan span = patch_span_m(inputs.patch, n);
  const double g = inputs.gap.gap_m;
  s.touches_gap_x_m = 0.0 - span.max_m / n.x();  // 0 - : no "-0" for a front parallel to the cut
  s.leaves_gap_x_m = (g - span.min_m) / n.x();
  s.touches_outgoing_rail_x_m = (g - span.max_m) / n.x();
  s.leaves_incoming_rail_x_m = 0.0 - span.min_m / n.x();

  // R is largest where the pressure is: sqrt(R) is concave in x_front while
  // the patch overlaps the gap (Brunn-Minkowski: both are convex), so one
  // maximum on [touches, leaves].
  const auto reduction = [&](double x) { return patch_gap_overlap(inputs.patch, inputs.gap, x).area_m2; };
  s.at_max_pressure = pressure_state(inputs, argmax_between(reduction, s.touches_gap_x_m, s.leaves_gap_x_m));

  const auto rate = [&](double x) { return pressure_state(inputs, x).rate_Pa_per_m; };
  const auto [rise_lo, rise_hi] = bracket_of_best_sample(traversal, [](const PressureState& p) { return p.rate_Pa_per_m; });
  s.at_max_rate = pressure_state(inputs, argmax_between(rate, rise_lo, rise_hi));
  const auto [fall_lo, fall_hi] = bracket_of_best_sample(traversal, [](const PressureState& p) { return -p.rate_Pa_per_m; });
  s.at_min_rate = pressure_state(inputs, argmax_between([&](double x) { return -rate(x); }, fall_lo, fall_hi));

  s.points = {point(1, "the patch's front reaches the gap: the pressure starts to rise", pressure_state(inputs, s.touches_gap_x_m)),
              point(2, "steepest rise of the pressure", s.at_max_rate),
              point(3, "highest pressure, rate zero (patch centred over the gap)", s.at_max_pressure),
              point(4, "steepest fall of the pressure", s.at_min_rate),
              point(5, "the patch's back leaves the gap: wholly on the outgoing rail end", pressure_state(inputs, s.leaves_gap_x_m))};

  if (inputs.patch.shape == PatchShape::ellipse) {
    HertzianCrossing h;
    h.static_peak_pressure_Pa = 1.5 * inputs.normal_force_N / s.initial_area_m2;
    const auto peak = [&](double x) {
      return hertzian_bearing(inputs.patch, inputs.gap, inputs.normal_force_N, x).peak_pressure_Pa;
    };
    std::vector<double> peaks(traversal.size());
    for (std::size_t i = 0; i < traversal.size(); ++i) peaks[i] = peak(traversal[i].x_front_m);
    // Every local maximum of the samples, refined; the highest, and those
    // that tie it. Brent's bracket of 1e-9 leaves the value within ~1e-16
    // of a smooth maximum: 1e-9 relative is far above that and far below
    // any real difference between two maxima.
    std::vector<std::pair<double, double>> maxima;  // (x, peak)
    for (std::size_t i = 0; i < peaks.size(); ++i) {
      const bool left = i == 0 || peaks[i] >= peaks[i - 1];
      const bool right = i + 1 == peaks.size() || peaks[i] > peaks[i + 1];
      if (!left || !right) continue;
      const double lo = traversal[i == 0 ? 0 : i - 1].x_front_m;
      const double hi = traversal[std::min(i + 1, traversal.size() - 1)].x_front_m;
      const double x = argmax_between(peak, lo, hi);
      maxima.emplace_back(x, peak(x));
    }
    double highest = 0.0;
    for (const auto& m : maxima) highest = std::max(highest, m.second);
    bool first = true;
    for (const auto& [x, value] : maxima) {
      if (value < highest * (1.0 - 1e-9)) continue;
      if (first) {
        h.x_at_max_peak_m = x;
        first = false;
      } else {
        h.x_at_tied_max_peak_m.push_back(x);
      }
    }
    const HertzianBearing at = hertzian_bearing(inputs.patch, inputs.gap, inputs.normal_force_N, h.x_at_max_peak_m);
    h.max_peak_pressure_Pa = at.peak_pressure_Pa;
    h.force_incoming_at_max_peak_N = at.force_incoming_N;
    h.force_outgoing_at_max_peak_N = at.force_outgoing_N;
    s.hertz = h;
  }
  return s;
}

std::vector<ThetaSweepRow> theta_sweep(const PressureInputs& base, double from_deg, double to_deg, int count) {
  std::vector<ThetaSweepRow> rows;
  rows.reserve(static_cast<std::size_t>(count));
  PressureInputs inputs = base;
  for (int i = 0; i < count; ++i) {
    const double theta_deg = count == 1 ? from_deg : from_deg + (to_deg - from_deg) * i / (count - 1);
    inputs.gap.theta_rad = theta_deg * std::numbers::pi / 180.0;
    const PressureSummary s = summarize_pressure(inputs, pressure_traversal(inputs));
    rows.push_back({theta_deg, s.g_long_m, s.at_max_pressure.pressure_Pa, s.max_relative_pressure(),
                    s.max_abs_rate_Pa_per_s(inputs.speed_m_per_s)});
  }
  return rows;
}

}  // namespace railjoint
