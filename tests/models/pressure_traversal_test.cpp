// The local model's traversal (models/pressure_traversal.h): the thesis's
// polygon mode against the thesis's own method (tests/models/thesis_local_model.h),
// hand-derived rectangle cases, the symmetry point, the closed-form maximum of
// the exact ellipse, and the five points of figure 6.3.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "models/hertz_contact.h"
#include "models/pressure_traversal.h"
#include "support/input_error.h"
#include "tests/models/thesis_local_model.h"

namespace railjoint {
namespace {

constexpr double kPi = std::numbers::pi;

double radians(double degrees) { return degrees * kPi / 180.0; }

// Table 6.1: N = 112.5 kN, a = 16 mm, b = 12 mm, g = 6 mm, v = 50 m/s, 1000 steps, 100 vertices.
PressureInputs table_6_1(double theta_deg, PatchShape shape = PatchShape::ellipse) {
  PressureInputs in;
  in.patch = ContactPatch{shape, 0.016, 0.012, 100};
  in.gap = EndPostGap{0.006, radians(theta_deg)};
  in.normal_force_N = 112.5e3;
  in.speed_m_per_s = 50.0;
  in.steps = 1000;
  return in;
}

class TableAngles : public testing::TestWithParam<double> {};

// Figure 6.3's point 3: with the patch centred over the gap the two shapes are
// point-symmetric about the same point, R(x) is even about it and its
// derivative zero; and R is largest there.
TEST_P(TableAngles, RateIsZeroAtTheSymmetryPointWherePressurePeaks) {
  const PressureInputs in = table_6_1(GetParam());
  const double b = in.patch.width_m;
  const double theta = in.gap.theta_rad;
  const double x_symmetric = (b * std::cos(theta) / std::sin(theta) + in.gap.gap_m / std::sin(theta)) / 2.0 +
                             in.patch.length_m / 2.0;
  const PressureState at = pressure_state(in, x_symmetric);
  const PressureSummary s = summarize_pressure(in, pressure_traversal(in));
  std::printf("theta = %g: x_sym = %.9f mm, rate there %.3e Pa/m (max %.3e), Brent's maximum at %.9f mm\n", GetParam(),
              x_symmetric * 1e3, at.rate_Pa_per_m, s.at_max_rate.rate_Pa_per_m, s.at_max_pressure.x_front_m * 1e3);
  EXPECT_LT(std::abs(at.rate_Pa_per_m), 1e-12 * s.at_max_rate.rate_Pa_per_m);
  // Brent to 2^-30 of the bracket: ~2e-11 m; the maximum is flat, so P agrees to round-off.
  EXPECT_NEAR(s.at_max_pressure.x_front_m, x_symmetric, 1e-9);
  EXPECT_NEAR(s.at_max_pressure.pressure_Pa, at.pressure_Pa, 1e-13 * at.pressure_Pa);
}

// The maximum in closed form: centred, the ellipse loses the band
// |s| <= u of the unit disc, u = g / (2h), h = sqrt((a/2 sin)^2 + (b/2 cos)^2)
// its half-extent across the cut: R_max = 2 (a/2)(b/2) [asin u + u sqrt(1 - u^2)].
TEST_P(TableAngles, HighestPressureHasItsClosedForm) {
  const PressureInputs in = table_6_1(GetParam());
  const double A = in.patch.length_m / 2.0;
  const double B = in.patch.width_m / 2.0;
  const double theta = in.gap.theta_rad;
  const double h = std::hypot(A * std::sin(theta), B * std::cos(theta));
  const double u = in.gap.gap_m / (2.0 * h);
  const double A0 = kPi * A * B;
  const double R_max = 2.0 * A * B * (std::asin(u) + u * std::sqrt(1.0 - u * u));
  const double expected = A0 / (A0 - R_max);
  const PressureSummary s = summarize_pressure(in, pressure_traversal(in));
  std::printf("theta = %g: max P/P0 = %.12f, closed form %.12f; P0 = %.6f MPa\n", GetParam(), s.max_relative_pressure(),
              expected, s.p0_Pa * 1e-6);
  EXPECT_NEAR(s.max_relative_pressure(), expected, 1e-13);
  EXPECT_NEAR(s.p0_Pa, 112.5e3 / A0, 1e-9 * s.p0_Pa);
}

// The polygon mode (Boost.Geometry) against the thesis's own method: the same
// n-gon clipped edge by edge, the shoelace formula, numpy.gradient.
TEST_P(TableAngles, PolygonModeMatchesTheThesissMethod) {
  const PressureInputs in = table_6_1(GetParam(), PatchShape::polygon);
  const std::vector<PressureState> ours = pressure_traversal(in);
  namespace ref = thesis_reference;
  const double a = in.patch.length_m;
  const double b = in.patch.width_m;
  const ref::Polygon joint = ref::thesis_parallelogram(b, in.gap.gap_m, in.gap.theta_rad);
  const double A0 = ref::shoelace_area(ref::thesis_polygon(a, b, 100, 0.0));
  std::vector<double> pressures;
  double worst_pressure = 0.0;
  for (const PressureState& state : ours) {
    const ref::Polygon over_gap = ref::clip_to_convex(ref::thesis_polygon(a, b, 100, state.x_front_m), joint);
    const double R = over_gap.size() < 3 ? 0.0 : ref::shoelace_area(over_gap);
    pressures.push_back(in.normal_force_N / (A0 - R));
    worst_pressure = std::max(worst_pressure, std::abs(state.pressure_Pa - pressures.back()) / pressures.back());
  }
  const double dx = ours[1].x_front_m - ours[0].x_front_m;
  const std::vector<double> gradient = ref::numpy_gradient(pressures, dx);
  double thesis_max_rate = 0.0;
  double our_max_rate = 0.0;
  double worst_rate = 0.0;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    thesis_max_rate = std::max(thesis_max_rate, std::abs(gradient[i]));
    our_max_rate = std::max(our_max_rate, std::abs(ours[i].rate_Pa_per_m));
  }
  for (std::size_t i = 0; i < ours.size(); ++i) {
    worst_rate = std::max(worst_rate, std::abs(ours[i].rate_Pa_per_m - gradient[i]) / thesis_max_rate);
  }
  std::printf("theta = %g: polygon mode vs thesis method: worst |dP|/P = %.2e; rate: worst |exact - numpy.gradient| / max "
              "= %.2e; max |rate| %.6e (exact, samples) vs %.6e Pa/m (numpy.gradient)\n",
              GetParam(), worst_pressure, worst_rate, our_max_rate, thesis_max_rate);
  // Both intersect the same polygons exactly: round-off only (measured ~1e-15).
  EXPECT_LT(worst_pressure, 1e-12);
  // The central difference errs by ~dx^2 P''' / 6, and by up to ~dx P'' where
  // a polygon vertex crosses a cut line between two samples (the exact rate of
  // a polygon jumps there): measured 6.8e-3 .. 1.9e-2 of the largest rate;
  // the largest rates 0.1-0.6 % apart.
  EXPECT_LT(worst_rate, 2e-2);
  EXPECT_NEAR(our_max_rate, thesis_max_rate, 1e-2 * thesis_max_rate);
}

// The Hertzian peak, like R, is point-symmetric about point 3 (the patch
// centred over the gap; the ellipse and the parallelogram are both
// point-symmetric): at x_sym + d the bearing part is that at x_sym - d turned
// half a turn, the rail ends swapped. So its maximum comes twice, at
// x_sym -+ d, with the loads swapped, and both are reported (the first as
// the peak, the other as a tie).
TEST_P(TableAngles, TheHertzianPeakComesTwiceWithTheRailEndsSwapped) {
  const PressureInputs in = table_6_1(GetParam());
  const PressureSummary s = summarize_pressure(in, pressure_traversal(in));
  ASSERT_TRUE(s.hertz);
  const HertzianCrossing& h = *s.hertz;
  ASSERT_EQ(h.x_at_tied_max_peak_m.size(), 1u);
  const double x1 = h.x_at_max_peak_m;
  const double x2 = h.x_at_tied_max_peak_m.front();
  const double x_sym = s.at_max_pressure.x_front_m;
  const HertzianBearing other = hertzian_bearing(in.patch, in.gap, in.normal_force_N, x2);
  std::printf("theta = %g: maxima at %.6f and %.6f mm about %.6f mm; loads %.3f / %.3f and %.3f / %.3f kN\n",
              GetParam(), 1e3 * x1, 1e3 * x2, 1e3 * x_sym, 1e-3 * h.force_incoming_at_max_peak_N,
              1e-3 * h.force_outgoing_at_max_peak_N, 1e-3 * other.force_incoming_N, 1e-3 * other.force_outgoing_N);
  EXPECT_LT(x1, x_sym);
  // Brent at a smooth maximum finds x to about sqrt(round-off) of its scale:
  // measured 2e-9 to 4e-9 m off the mirror at 45-90 deg (0 at 30 deg).
  EXPECT_NEAR(x1 + x2, 2.0 * x_sym, 2e-8);
  EXPECT_NEAR(other.peak_pressure_Pa, h.max_peak_pressure_Pa, 1e-9 * h.max_peak_pressure_Pa);
  // The loads swapped, to their slope (N over some 7 mm: 1.7e7 N/m) times
  // those 2e-8 m: measured up to 0.07 N.
  EXPECT_NEAR(other.force_outgoing_N, h.force_incoming_at_max_peak_N, 0.5);
  EXPECT_NEAR(other.force_incoming_N, h.force_outgoing_at_max_peak_N, 0.5);
}

INSTANTIATE_TEST_SUITE_P(Table61, TableAngles, testing::Values(30.0, 45.0, 60.0, 90.0));

// Figures 5.2-5.4's rectangle, a = 14, b = 10, g = 6 (mm), by hand.
TEST(RectanglePatch, SquareJointByHand) {
  PressureInputs in;
  in.patch = ContactPatch{PatchShape::rectangle, 0.014, 0.010, 4};
  in.gap = EndPostGap{0.006, kPi / 2.0};
  in.normal_force_N = 1.0;
  // R = b * |[x - a, x] n [0, g]|: at x = 3 mm 3 x 10, at 10 mm the whole gap 6 x 10, at 16 mm [2, 6] x 10.
  // dR/dx: +b while the front is in the gap, 0 while the gap is covered, -b as the back crosses.
  struct Case {
    double x_mm, R_mm2, dR_dx_mm;
  };
  for (const Case& c : {Case{3.0, 30.0, 10.0}, Case{10.0, 60.0, 0.0}, Case{16.0, 40.0, -10.0}}) {
    const PressureState s = pressure_state(in, c.x_mm * 1e-3);
    const double A = (140.0 - c.R_mm2) * 1e-6;
    EXPECT_NEAR(s.reduction_area_m2, c.R_mm2 * 1e-6, 1e-15) << c.x_mm;
    EXPECT_NEAR(s.active_area_m2, A, 1e-15) << c.x_mm;
    // dP/dx = N (dR/dx) / A^2
    EXPECT_NEAR(s.rate_Pa_per_m, c.dR_dx_mm * 1e-3 / (A * A), 1e-9 * std::abs(1.0 / (A * A))) << c.x_mm;
  }
  const PressureSummary summary = summarize_pressure(in, pressure_traversal(in));
  EXPECT_NEAR(summary.max_relative_pressure(), 140.0 / 80.0, 1e-12);
}

TEST(RectanglePatch, FortyFiveDegreesByHand) {
  PressureInputs in;
  in.patch = ContactPatch{PatchShape::rectangle, 0.014, 0.010, 4};
  in.gap = EndPostGap{0.006, kPi / 4.0};
  in.normal_force_N = 1.0;
  // Gap: 0 <= x - y <= g_long = 6 sqrt 2 (mm), 0 <= y <= 10. Front at x = 5 mm:
  // at height y the gap from y to 5 lies under the patch: R = int_0^5 (5 - y) dy = 12.5 mm^2,
  // dR/dx = 5 mm (the near cut inside the patch spans y in [0, 5]).
  PressureState s = pressure_state(in, 0.005);
  EXPECT_NEAR(s.reduction_area_m2, 12.5e-6, 1e-15);
  EXPECT_NEAR(s.rate_Pa_per_m, 5e-3 / std::pow(127.5e-6, 2), 1e-9 / std::pow(127.5e-6, 2));
  // Centred (x = (10 + 6 sqrt 2)/2 + 7 = 12 + 3 sqrt 2 mm): with c = 3 sqrt 2 - 2 the patch's back,
  // R = 2 int_0^c (y + 3 sqrt 2 + 2) dy + 6 sqrt 2 (10 - 2c) = 2 (25 - 6 sqrt 2) + 84 sqrt 2 - 72
  //   = 72 sqrt 2 - 22 mm^2, and P/P0 = 140 / (162 - 72 sqrt 2).
  const double root2 = std::sqrt(2.0);
  s = pressure_state(in, (12.0 + 3.0 * root2) * 1e-3);
  EXPECT_NEAR(s.reduction_area_m2, (72.0 * root2 - 22.0) * 1e-6, 1e-15);
  EXPECT_NEAR(s.rate_Pa_per_m, 0.0, 1e-6 / std::pow(s.active_area_m2, 2));
  const PressureSummary summary = summarize_pressure(in, pressure_traversal(in));
  std::printf("rectangle 14 x 10, g 6, 45 deg: max P/P0 = %.12f, by hand %.12f\n", summary.max_relative_pressure(),
              140.0 / (162.0 - 72.0 * root2));
  EXPECT_NEAR(summary.max_relative_pressure(), 140.0 / (162.0 - 72.0 * root2), 1e-12);
}

// Figure 6.3 at 30 deg: the five points in order, at the closed-form touches,
// with the rate zero outside the gap and extreme at points 2 and 4.
TEST(PointsOfInterest, FigureSixThreeAtThirtyDegrees) {
  const PressureInputs in = table_6_1(30.0);
  const std::vector<PressureState> traversal = pressure_traversal(in);
  const PressureSummary s = summarize_pressure(in, traversal);
  for (const PointOfInterest& p : s.points) {
    std::printf("point %d at x = %8.4f mm, t = %.4f ms: P/P0 = %.5f, dP/dt = %+.4e Pa/s  (%s)\n", p.number,
                p.state.x_front_m * 1e3, p.state.x_front_m / in.speed_m_per_s * 1e3, p.state.pressure_Pa / s.p0_Pa,
                p.state.rate_Pa_per_m * in.speed_m_per_s, p.what.c_str());
  }
  for (int i = 0; i + 1 < 5; ++i) EXPECT_LT(s.points[i].state.x_front_m, s.points[i + 1].state.x_front_m);
  // Point 1: the ellipse's support along n = (sin, -cos) reaches 0:
  // sin (x - a/2) - cos b/2 + h = 0, h = sqrt((a/2 sin)^2 + (b/2 cos)^2).
  const double theta = in.gap.theta_rad;
  const double h = std::hypot(0.008 * std::sin(theta), 0.006 * std::cos(theta));
  EXPECT_NEAR(s.points[0].state.x_front_m, 0.008 + (0.006 * std::cos(theta) - h) / std::sin(theta), 1e-15);
  EXPECT_NEAR(s.points[4].state.x_front_m, 0.008 + (0.006 + 0.006 * std::cos(theta) + h) / std::sin(theta), 1e-15);
  EXPECT_NEAR(s.points[0].state.pressure_Pa, s.p0_Pa, 1e-12 * s.p0_Pa);
  EXPECT_NEAR(s.points[4].state.pressure_Pa, s.p0_Pa, 1e-12 * s.p0_Pa);
  for (const PressureState& state : traversal) {
    EXPECT_LE(state.rate_Pa_per_m, s.at_max_rate.rate_Pa_per_m * (1.0 + 1e-12));
    EXPECT_GE(state.rate_Pa_per_m, s.at_min_rate.rate_Pa_per_m * (1.0 + 1e-12));
  }
  // Both shapes are point-symmetric: the fall mirrors the rise.
  EXPECT_NEAR(s.at_min_rate.rate_Pa_per_m, -s.at_max_rate.rate_Pa_per_m, 1e-9 * s.at_max_rate.rate_Pa_per_m);
}

// Sections 6.2-6.4: a smaller junction angle gives a higher peak pressure
// and, far below the practical range, a much slower change; between 45 and
// 90 deg the rate hardly changes (the thesis: "no significant differences";
// measured: its maximum lies at 58.5 deg, 1.1 % above the square joint's).
TEST(ThetaSweep, PressureFallsWithTheAngleAndTheRateRisesTowardsTheSquareJoint) {
  const std::vector<ThetaSweepRow> rows = theta_sweep(table_6_1(30.0), 1.0, 90.0, 100);
  ASSERT_EQ(rows.size(), 100u);
  EXPECT_DOUBLE_EQ(rows.front().theta_deg, 1.0);
  EXPECT_DOUBLE_EQ(rows.back().theta_deg, 90.0);
  const auto highest_rate = std::max_element(rows.begin(), rows.end(), [](const ThetaSweepRow& l, const ThetaSweepRow& r) {
    return l.max_rate_Pa_per_s < r.max_rate_Pa_per_s;
  });
  std::printf("theta 1 deg: max P/P0 %.4f, |dP/dt| %.4e Pa/s; 90 deg: %.4f, %.4e Pa/s; fastest at %.2f deg (%.4e Pa/s)\n",
              rows.front().max_relative_pressure, rows.front().max_rate_Pa_per_s, rows.back().max_relative_pressure,
              rows.back().max_rate_Pa_per_s, highest_rate->theta_deg, highest_rate->max_rate_Pa_per_s);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_LT(rows[i].max_pressure_Pa, rows[i - 1].max_pressure_Pa) << rows[i].theta_deg;
    if (rows[i].theta_deg <= 45.0) {
      EXPECT_GT(rows[i].max_rate_Pa_per_s, rows[i - 1].max_rate_Pa_per_s) << rows[i].theta_deg;
    }
  }
  EXPECT_LT(rows.front().max_rate_Pa_per_s, 0.1 * rows.back().max_rate_Pa_per_s) << "1 deg: a far slower change";
  EXPECT_NEAR(highest_rate->max_rate_Pa_per_s, rows.back().max_rate_Pa_per_s, 0.02 * rows.back().max_rate_Pa_per_s);
  const PressureInputs square = table_6_1(90.0);
  const PressureSummary s = summarize_pressure(square, pressure_traversal(square));
  EXPECT_NEAR(rows.back().max_rate_Pa_per_s, s.max_abs_rate_Pa_per_s(50.0), 1e-9 * rows.back().max_rate_Pa_per_s);
}

TEST(PressureInputsCheck, RefusesNoGapAndAGapWiderThanThePatch) {
  PressureInputs in = table_6_1(30.0);
  in.gap.gap_m = 0.0;
  try {
    check_pressure_inputs(in);
    FAIL() << "a zero gap must be refused";
  } catch (const InputError& error) {
    EXPECT_EQ(error.key(), "joint.gap");
    EXPECT_NE(std::string(error.what()).find("never leaves"), std::string::npos) << error.what();
  }
  // Across the cut at 90 deg the ellipse is a = 16 mm wide.
  in = table_6_1(90.0);
  in.gap.gap_m = 0.016;
  EXPECT_THROW(check_pressure_inputs(in), InputError);
  in.gap.gap_m = 0.0159;
  EXPECT_NO_THROW(check_pressure_inputs(in));
}

}  // namespace
}  // namespace railjoint
