// One contact where the two rail ends' patches merge (sim/rail_end_patch_share.h):
// its limits and invariants, and the force it gives against the boundary-
// element solution of one elastic body with both rail ends' surfaces
// (models/normal_contact_solver.h, checked against Hertz and Boussinesq in
// tests/models), where the sum of two Hertz springs counts one patch twice.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "models/half_space_influence.h"
#include "models/hertz_contact.h"
#include "models/hertz_ellipse.h"
#include "models/normal_contact_solver.h"
#include "sim/rail_end_patch_share.h"

namespace railjoint {
namespace {

TEST(RailEndPatchShare, ApartEachCarriesItsOwn) {
  const auto s = merged_patch_shares({-0.014, 0.006, 1e5}, {0.014, 0.007, 3e5});
  EXPECT_EQ(s[0], 1.0);
  EXPECT_EQ(s[1], 1.0);
}

TEST(RailEndPatchShare, OneNotBearingLeavesTheOther) {
  const auto s = merged_patch_shares({0.0, 0.006, 1e5}, {0.001, 0.0, 0.0});
  EXPECT_EQ(s[0], 1.0);
}

TEST(RailEndPatchShare, CoincidentPatchesAreOneContact) {
  // Same point, same load: the sum of the carried forces is one patch's.
  const auto s = merged_patch_shares({0.001, 0.006, 1e5}, {0.001, 0.006, 1e5});
  EXPECT_NEAR(s[0] * 1e5 + s[1] * 1e5, 1e5, 1e-9 * 1e5);
}

TEST(RailEndPatchShare, ContinuousAsTheSecondLoadVanishes) {
  // The second patch's load -> 0 (its semi-length as F^(1/3)): the first's
  // share -> 1, so the total is continuous at the second rail's onset.
  double last = 0.0;
  for (double f : {1e3, 1e1, 1e-1, 1e-3}) {
    const auto s = merged_patch_shares({0.0, 0.006, 1e5}, {0.002, 0.006 * std::cbrt(f / 1e5), f});
    EXPECT_GE(s[0], last);
    last = s[0];
  }
  EXPECT_GT(last, 1.0 - 1e-6);
}

TEST(RailEndPatchShare, CarriedTotalIsTheUpperEnvelopeOfTheTwoDensities) {
  // Independent check of the piecewise integration: the carried total is
  // the integral of max(q_0, q_1), here by a fine midpoint rule (1e6 cells).
  const RailEndPatch p0{-0.002, 0.006, 1.2e5}, p1{0.003, 0.008, 2.5e5};
  auto q = [](const RailEndPatch& p, double x) {
    const double u = (x - p.x_m) / p.semi_length_m;
    return std::abs(u) < 1.0 ? 0.75 * p.force_N / p.semi_length_m * (1.0 - u * u) : 0.0;
  };
  const double lo = -0.01, hi = 0.012;
  const int n = 1000000;
  double envelope_N = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = lo + (i + 0.5) * (hi - lo) / n;
    envelope_N += std::max(q(p0, x), q(p1, x)) * (hi - lo) / n;
  }
  const auto s = merged_patch_shares(p0, p1);
  EXPECT_NEAR(s[0] * p0.force_N + s[1] * p1.force_N, envelope_N, 1e-6 * envelope_N);
}

// The rail ends of a dipped joint with a closed gap, each falling at beta
// towards the joint (the surface beta |x|, the cut at x = 0), under a
// cylindrical wheel (R_x 0.475 m) on a crowned head (R_y 0.3 m): the gap of
// the undeformed bodies h(x, y) = (x - x_w)^2 / (2 R_x) - beta |x| +
// y^2 / (2 R_y), less its minimum. The boundary-element solution is one
// elastic body under both rail ends, so it counts the patch once.
struct DipCase {
  double beta;
  double wheel_x_m;
};

constexpr double kRx = 0.475, kRy = 0.3;

// Rail end i's smallest gap on its own side (x <= 0 for rail 0, >= 0 for
// rail 1) and where: the parabola's vertex, held on that side.
struct SideMinimum {
  double x_m, gap_m;
};
SideMinimum side_minimum(double beta, double wheel_x_m, int rail) {
  const double sign = rail == 0 ? 1.0 : -1.0;  // rail 0: + beta x (x <= 0), rail 1: - beta x
  double x = wheel_x_m - sign * kRx * beta;
  x = rail == 0 ? std::min(x, 0.0) : std::max(x, 0.0);
  return {x, (x - wheel_x_m) * (x - wheel_x_m) / (2 * kRx) + sign * beta * x};
}

TEST(RailEndPatchShare, SpanningContactMatchesOneElasticBody) {
  const double load_N = 150e3;
  const HertzMaterial steel;  // E 210 GPa, nu 0.3
  const double e_star = combined_modulus_Pa(steel.youngs_modulus_Pa, steel.poisson_ratio, steel.youngs_modulus_Pa,
                                            steel.poisson_ratio);
  const auto hertz = elliptical_hertz({0.5 / kRx, 0.5 / kRy}, steel);
  ASSERT_TRUE(hertz.has_value());
  const double G = hertz->hertz_constant_m_per_N2_3;
  const int nx = 160, ny = 48;
  const double cell_m = 0.4e-3;
  const HalfSpaceConvolution convolution(nx, ny, cell_m, cell_m, e_star);
  std::vector<double> sum_errors, merged_errors, spanning_errors;
  std::printf("beta      x_w [mm]  lesser/load  sum of two  merged   spanning  conservative  (force at the BEM's approach / load - 1)  apart\n");
  for (double beta : {1e-6, 1e-3, 2e-3, 3e-3, 4e-3, 5e-3, 7e-3, 1e-2, 2e-2, 3e-2}) {
    for (double wheel_x_m : {0.0, 1.5e-3, -4e-3, 3e-3, 8e-3}) {
      const SideMinimum m0 = side_minimum(beta, wheel_x_m, 0), m1 = side_minimum(beta, wheel_x_m, 1);
      const double h_min = std::min(m0.gap_m, m1.gap_m);
      NormalContactProblem problem;
      problem.gap_m.resize(nx, ny);
      for (int i = 0; i < nx; ++i) {
        for (int j = 0; j < ny; ++j) {
          const double x = (i - nx / 2 + 0.5) * cell_m, y = (j - ny / 2 + 0.5) * cell_m;
          problem.gap_m(i, j) =
              (x - wheel_x_m) * (x - wheel_x_m) / (2 * kRx) - beta * std::abs(x) + y * y / (2 * kRy) - h_min;
        }
      }
      problem.normal_force_N = load_N;
      const NormalContactSolution s = solve_normal_contact(problem, convolution);
      ASSERT_TRUE(s.converged);
      // Hertz per rail end at the same approach, its penetration the
      // approach less its own gap, its patch Hertz's semi-axis along x.
      std::array<RailEndPatch, 2> patch;
      const SideMinimum mins[2] = {m0, m1};
      for (int i = 0; i < 2; ++i) {
        const double penetration_m = s.approach_m - (mins[i].gap_m - h_min);
        const double force_N = penetration_m > 0 ? std::pow(penetration_m / G, 1.5) : 0.0;
        patch[i] = {mins[i].x_m, force_N > 0 ? hertz_patch(*hertz, force_N).semi_axis_x_m : 0.0, force_N};
      }
      const auto share = merged_patch_shares(patch[0], patch[1]);
      const double sum_N = patch[0].force_N + patch[1].force_N;
      const double merged_N = share[0] * patch[0].force_N + share[1] * patch[1].force_N;
      sum_errors.push_back(sum_N / load_N - 1);
      merged_errors.push_back(merged_N / load_N - 1);
      // The spanning contact: the same, each penetration less the other's
      // load's approach there.
      const auto patch_at = [&](int i, double penetration_m) -> RailEndPatch {
        if (!(penetration_m > 0.0)) return {mins[i].x_m, 0.0, 0.0};
        const double force_N = std::pow(penetration_m / G, 1.5);
        return {mins[i].x_m, hertz_patch(*hertz, force_N).semi_axis_x_m, force_N};
      };
      const SpanningContact spanning = spanning_contact(
          {s.approach_m - (m0.gap_m - h_min), s.approach_m - (m1.gap_m - h_min)}, patch_at, e_star);
      double spanning_N = 0.0;
      for (int i = 0; i < 2; ++i) spanning_N += spanning.share[i] * patch_at(i, spanning.effective_penetration_m[i]).force_N;
      spanning_errors.push_back(spanning_N / load_N - 1);
      // Its conservative variant (the gradient of the energy the force run
      // books): the same model less the merged law's own work.
      const SpanningContact conservative = conservative_spanning_contact(
          {s.approach_m - (m0.gap_m - h_min), s.approach_m - (m1.gap_m - h_min)}, patch_at, e_star);
      double conservative_N = 0.0;
      for (int i = 0; i < 2; ++i)
        conservative_N += conservative.share[i] * patch_at(i, conservative.effective_penetration_m[i]).force_N;
      const double conservative_error = conservative_N / load_N - 1;
      const double lesser = std::min(share[0] * patch[0].force_N, share[1] * patch[1].force_N) / load_N;
      // The touching points' distance over the larger patch's semi-length
      // at the spanning contact's penetrations, as the force run measures it
      // (HertzAtPeak::spanning_apart, at the geometric penetrations).
      const double semi_m = std::max(patch[0].semi_length_m, patch[1].semi_length_m);
      const double apart = std::abs(m0.x_m - m1.x_m) / semi_m;
      std::printf("%-9.0e %6.1f     %6.3f     %+8.3f   %+8.3f  %+8.4f   %+8.4f      %6.3f\n", beta, 1e3 * wheel_x_m,
                  lesser, sum_errors.back(), merged_errors.back(), spanning_errors.back(), conservative_error, apart);
      if (lesser == 0.0) {
        // One rail end alone: Hertz, to the solver's 0.4 mm cells (Hertz's
        // peak to 1 %, the load-approach to ~1e-3), whatever the model.
        EXPECT_LT(std::abs(sum_errors.back()), 2e-3);
        EXPECT_LT(std::abs(spanning_errors.back()), 2e-3);
      } else if (lesser > 0.1) {
        // Both bear: the sum of two springs overstates the force by more
        // than the force runs' 1 % target (13-100 %; the evidence for the
        // coupled contact).
        EXPECT_GT(sum_errors.back(), 0.05) << beta << " " << wheel_x_m;
      }
      // The conservative variant differs from the merged law by the
      // merged law's own work's force, E_H ds / d(delta) + ...: measured at
      // most 0.6 % of the load with the touching points a patch semi-length
      // apart or more, -1.7 % to +1.2 % nearer (within 0.88 % of one elastic
      // body apart, -3.9 % to +12.2 % nearer, as the merged law's 0.84 % and
      // -2.9 % to +13.3 %). Allowed: 2.5 %.
      EXPECT_LT(std::abs(conservative_error - spanning_errors.back()), 2.5e-2) << beta << " " << wheel_x_m;
      // Never worse than either simpler model.
      EXPECT_LE(std::abs(spanning_errors.back()), std::abs(merged_errors.back()) + 2e-3);
      EXPECT_LE(std::abs(merged_errors.back()), std::abs(sum_errors.back()) + 1e-9);
      // The touching points a patch semi-length apart or more: one elastic
      // body's force within 1 %, the run's vouched range (measured 0.9 %);
      // nearer, the documented -3 % to +14 % (measured -3.1 % where the
      // patches just touch, +13.3 % with one point at a rail end's corner).
      if (apart >= kSpanningContactVouchedApart) {
        EXPECT_LT(std::abs(spanning_errors.back()), 1e-2) << beta << " " << wheel_x_m;
      } else {
        EXPECT_GT(spanning_errors.back(), -0.035) << beta << " " << wheel_x_m;
        EXPECT_LT(spanning_errors.back(), 0.15) << beta << " " << wheel_x_m;
      }
    }
  }
}

}  // namespace
}  // namespace railjoint
