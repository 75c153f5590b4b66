// The edge pressure (models/rail_end_edge_load.h) on a field given in closed
// form: p = K / sqrt(n) at the distance n from a rail end's cut, the
// leading term of an elastic contact at a sharp edge (the flat punch's).
// Its mean over 0 <= n <= L is (1/L) int_0^L K n^-1/2 dn = 2 K / sqrt(L),
// whatever the position along the edge.

#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "models/rail_end_edge_load.h"
#include "models/rail_top.h"

namespace railjoint {
namespace {

constexpr double kK = 4e7;  // [Pa m^0.5], near table 6.1's joint's (3.2 GPa over 1 mm: K ~ 5e7)

struct Field {
  JointParams joint;
  RailEndGap gap;
  Eigen::ArrayXXd pressure_Pa;
};

// Cells of h x h around the gap's centre; the field on rail `loaded`, each
// cell its exact mean of K / sqrt(n) across the row (n from the cut at the
// row's centre line, x to x + h: the mean of n^-1/2 over [n1, n2] is
// 2 (sqrt(n2) - sqrt(n1)) / (n2 - n1)).
Field field(double theta_deg, double h_m, int loaded) {
  Field f;
  f.joint.theta_rad = theta_deg * std::numbers::pi / 180.0;
  f.joint.gap_m = 0.006;
  f.joint.beta_rad = 0.0;
  const int n = static_cast<int>(std::lround(0.024 / h_m));
  f.gap.dx_m = f.gap.dy_m = h_m;
  // A cell boundary on the cuts at y = 0 for theta = 90 deg: the field there is exact.
  f.gap.x0_m = cut_x_m(f.joint, 0.0, 0) - 0.5 * h_m - (n / 2) * h_m;
  f.gap.y0_m = -(n / 2) * h_m;
  f.gap.gap_m = Eigen::ArrayXXd::Zero(n, n);
  f.gap.no_surface.resize(n, n);
  f.gap.incoming.resize(n, n);
  f.pressure_Pa = Eigen::ArrayXXd::Zero(n, n);
  const double s = std::sin(f.joint.theta_rad);
  for (int j = 0; j < n; ++j) {
    const double y = f.gap.y0_m + j * h_m;
    for (int i = 0; i < n; ++i) {
      const double x = f.gap.x0_m + i * h_m;
      const bool in = x <= cut_x_m(f.joint, y, 0), out = x >= cut_x_m(f.joint, y, 1);
      f.gap.incoming(i, j) = in;
      f.gap.no_surface(i, j) = !in && !out;
      if (!(loaded == 0 ? in : out)) continue;
      // Distances normal to the cut of the cell's two sides, clipped at the cut.
      const double cut = cut_x_m(f.joint, y, loaded);
      double a = std::max(0.0, (loaded == 0 ? cut - x - 0.5 * h_m : x - 0.5 * h_m - cut) * s);
      const double b = (loaded == 0 ? cut - x + 0.5 * h_m : x + 0.5 * h_m - cut) * s;
      if (a < 1e-9 * h_m) a = 0.0;  // rounding on the cut, which sqrt would lift to 1e-8 of the cell's mean
      f.pressure_Pa(i, j) = kK * 2.0 * (std::sqrt(b) - std::sqrt(a)) / (b - a);
    }
  }
  return f;
}

// A square cut with cells on it: each cell carries the field's own mean, so
// the band's cells hold exactly 2 K sqrt(L) per unit length of edge
// (rounding: 1e-13 measured; 1e-12).
TEST(RailEndEdgeLoad, ASquareCutOnTheCellsGivesTheClosedForm) {
  for (int rail = 0; rail < 2; ++rail) {
    const Field f = field(90.0, 0.1e-3, rail);
    const double L = 1e-3;
    const RailEndEdgeLoad e = rail_end_edge_load(f.joint, f.gap, f.pressure_Pa, L);
    std::printf("rail %d: %.6f MPa against %.6f MPa, at (%.3f, %.3f) mm\n", rail, 1e-6 * e.mean_pressure_Pa,
                1e-6 * 2.0 * kK / std::sqrt(L), 1e3 * e.x_m, 1e3 * e.y_m);
    EXPECT_EQ(e.rail, rail);
    EXPECT_NEAR(e.mean_pressure_Pa, 2.0 * kK / std::sqrt(L), 1e-12 * 2.0 * kK / std::sqrt(L));
    EXPECT_NEAR(e.x_m, cut_x_m(f.joint, e.y_m, rail), 1e-12);  // on the cut line
  }
}

// An inclined cut crosses the cells: a cell whose centre is on the rail
// counts whole though part of it lies beyond the cut (the discrete edge is
// a staircase), and the worst square picks the rows where that adds most.
// The error falls as the cells shrink against L (measured at 30 deg,
// L = 1 mm: +7.3 % at 0.2 mm cells, +3.2 % at 0.1 mm, +0.67 % at 0.05 mm).
TEST(RailEndEdgeLoad, AnInclinedCutConvergesOnTheClosedForm) {
  const double L = 1e-3;
  const double expected = 2.0 * kK / std::sqrt(L);
  double previous = 1.0;
  for (const double h : {0.2e-3, 0.1e-3, 0.05e-3}) {
    const Field f = field(30.0, h, 0);
    const RailEndEdgeLoad e = rail_end_edge_load(f.joint, f.gap, f.pressure_Pa, L);
    const double error = e.mean_pressure_Pa / expected - 1.0;
    std::printf("30 deg, cells %.2f mm: %.3f MPa against %.3f MPa (%+.3f %%)\n", 1e3 * h, 1e-6 * e.mean_pressure_Pa,
                1e-6 * expected, 100.0 * error);
    EXPECT_EQ(e.rail, 0);
    EXPECT_LT(std::abs(error), 0.1);
    EXPECT_LT(std::abs(error), 0.6 * previous);  // converges: at least 0.6 a halving (0.43 and 0.21 measured)
    if (h < 0.06e-3) {
      EXPECT_LT(std::abs(error), 0.015);
    }
    previous = std::abs(error);
  }
}

}  // namespace
}  // namespace railjoint
