#pragma once
// The local model's traversal (thesis sections 5.2 and 6.2-6.4): the patch's
// front moves from x_front = 0 (touching the gap's first corner) to
// x_end = b cot(theta) + g_long + a in `steps` equal steps (the thesis's
// get_xs), at constant speed v (t = x / v). At each position: the reduction
// area R, the active area A = A0 - R, the uniform pressure P = N / A, P / P0,
// and the exact rate dP/dx = N (dR/dx) / A^2, dP/dt = v dP/dx.
// Maxima are refined between samples (Brent's method on the exact
// quantities), so they do not depend on the step count.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "models/contact_patch.h"
#include "models/end_post_gap.h"

namespace railjoint {

struct PressureInputs {
  ContactPatch patch;
  EndPostGap gap;
  double normal_force_N = 112.5e3;  ///< N, constant during the crossing (table 6.1) [N]
  double speed_m_per_s = 50.0;      ///< v (table 6.1) [m/s]
  int steps = 1000;                 ///< positions over the traversal, ends included (table 6.1)
};

/// Throws InputError (key "joint.gap", "contact_patch...") when the model
/// has nothing to say: no gap (the patch never leaves the rail), or a gap at
/// least as wide as the patch across the cut (no bearing area left).
void check_pressure_inputs(const PressureInputs& inputs);

/// x_end = b cot(theta) + g_long + a [m]: the thesis's end of the traversal.
double traversal_end_m(const PressureInputs& inputs);

struct PressureState {
  double x_front_m = 0.0;
  double reduction_area_m2 = 0.0;  ///< R
  double active_area_m2 = 0.0;     ///< A = A0 - R
  double pressure_Pa = 0.0;        ///< P = N / A
  double rate_Pa_per_m = 0.0;      ///< dP/dx_front (signed)
};

PressureState pressure_state(const PressureInputs& inputs, double x_front_m);

/// `steps` states from x_front = 0 to x_end.
std::vector<PressureState> pressure_traversal(const PressureInputs& inputs);

/// The five points of interest of figure 6.3.
struct PointOfInterest {
  int number = 0;
  std::string what;
  PressureState state;
};

/// The Hertzian pressure over the crossing (ellipse patches only).
struct HertzianCrossing {
  double static_peak_pressure_Pa = 0.0;  ///< 3 N / (2 pi (a/2)(b/2)): the whole patch bearing [Pa]
  double max_peak_pressure_Pa = 0.0;     ///< highest local pressure during the crossing [Pa]
  double x_at_max_peak_m = 0.0;
  double force_incoming_at_max_peak_N = 0.0;
  double force_outgoing_at_max_peak_N = 0.0;
  /// Other maxima as high (within 1e-9; a patch centred on the cut's
  /// normal is symmetric about point 3, so the peak comes twice with the
  /// rail ends' loads swapped); x_at_max_peak_m is then the first.
  std::vector<double> x_at_tied_max_peak_m;
};

struct PressureSummary {
  double initial_area_m2 = 0.0;  ///< A0
  double p0_Pa = 0.0;            ///< P0 = N / A0
  double g_long_m = 0.0;
  double x_end_m = 0.0;
  PressureState at_max_pressure;  ///< point 3: R largest, dP/dx = 0
  PressureState at_max_rate;      ///< point 2: steepest rise
  PressureState at_min_rate;      ///< point 4: steepest fall (negative rate)
  double touches_gap_x_m = 0.0;         ///< point 1: the patch's front reaches the gap
  double leaves_gap_x_m = 0.0;          ///< point 5: its back leaves the gap
  double touches_outgoing_rail_x_m = 0.0;  ///< the thesis's reading of point 2
  double leaves_incoming_rail_x_m = 0.0;   ///< the thesis's reading of point 4
  std::array<PointOfInterest, 5> points;
  std::optional<HertzianCrossing> hertz;  ///< ellipse patches only

  double max_relative_pressure() const { return at_max_pressure.pressure_Pa / p0_Pa; }
  /// Largest |dP/dt| over the crossing [Pa/s].
  double max_abs_rate_Pa_per_s(double speed_m_per_s) const;
};

/// Extrema refined from the samples of `traversal` (from pressure_traversal).
PressureSummary summarize_pressure(const PressureInputs& inputs, const std::vector<PressureState>& traversal);

/// Figures 6.5/6.6 and the appendix's max-stress-against-theta sweep: the
/// maxima for `count` junction angles evenly from `from_deg` to `to_deg`.
struct ThetaSweepRow {
  double theta_deg = 0.0;
  double g_long_m = 0.0;
  double max_pressure_Pa = 0.0;
  double max_relative_pressure = 0.0;
  double max_rate_Pa_per_s = 0.0;  ///< largest |dP/dt|
};
std::vector<ThetaSweepRow> theta_sweep(const PressureInputs& base, double from_deg, double to_deg, int count);

}  // namespace railjoint
