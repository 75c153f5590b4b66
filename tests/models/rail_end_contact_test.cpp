// The solved contact crossing the end-post gap (models/rail_end_contact.h):
// invariants that hold whatever the solver's accuracy: the two rail ends
// carry the load between them at every step, a closed gap makes the cut
// invisible (no dependence on theta), and an open gap lifts the peak at a
// rail end's edge.

#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "models/rail_end_contact.h"
#include "models/rail_top.h"

namespace railjoint {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Table 6.1's joint (theta 30 deg, g 6 mm, 112.5 kN) on a 300 mm crown, no
// dip (the local model's beta ~ 0), on a coarse grid to keep the test fast.
struct Case {
  JointParams joint;
  WheelParams wheel;
  RailEndContactSettings settings;
  Case(double theta_deg, double gap_m) {
    joint.theta_rad = theta_deg * kDeg;
    joint.gap_m = gap_m;
    joint.beta_rad = 0.0;
    joint.crown_radius_m = 0.3;
    settings.cells_x = 64;
    settings.cells_y = 48;
  }
};

constexpr double kLoad = 112.5e3;

TEST(RailEndContact, TheTwoEndsCarryTheLoadAtEveryStep) {
  Case c(30.0, 0.006);
  c.settings.height_mismatch_m = 20e-6;
  const RailEndCrossing crossing = rail_end_crossing(c.joint, c.wheel, c.settings, kLoad, 21);
  for (const RailEndStep& s : crossing.steps) {
    std::printf("x %+.2f mm: in %.1f N, out %.1f N, peak %.3f GPa, area %.2f mm^2, %d it\n", 1e3 * s.x_wheel_m,
                s.force_incoming_N, s.force_outgoing_N, 1e-9 * s.max_pressure_Pa, 1e6 * s.contact_area_m2,
                s.iterations);
    // The solver holds the load to rounding (sum of ~3000 cells): 1e-10.
    EXPECT_NEAR(s.force_incoming_N + s.force_outgoing_N, kLoad, 1e-10 * kLoad);
    EXPECT_TRUE(s.converged);
  }
  EXPECT_EQ(crossing.steps.front().force_outgoing_N, 0.0);  // wholly on the incoming rail
  EXPECT_EQ(crossing.steps.back().force_incoming_N, 0.0);   // wholly on the outgoing rail
}

TEST(RailEndContact, AClosedGapDoesNotDependOnTheCut) {
  const RailEndCrossing at30 = rail_end_crossing(Case(30.0, 0.0).joint, Case(30.0, 0.0).wheel,
                                                 Case(30.0, 0.0).settings, kLoad, 5);
  const RailEndCrossing at60 = rail_end_crossing(Case(60.0, 0.0).joint, Case(60.0, 0.0).wheel,
                                                 Case(60.0, 0.0).settings, kLoad, 5);
  const double peak30 = at30.steps[at30.peak_step].max_pressure_Pa;
  const double peak60 = at60.steps[at60.peak_step].max_pressure_Pa;
  std::printf("closed gap: peak %.6f GPa at 30 deg, %.6f GPa at 60 deg\n", 1e-9 * peak30, 1e-9 * peak60);
  // One continuous surface whatever theta: the same problem at every step,
  // solved to the solver's tolerance (1e-10 on the pressure's change).
  EXPECT_NEAR(peak30, peak60, 1e-7 * peak30);
  for (const RailEndStep& s : at30.steps) EXPECT_NEAR(s.max_pressure_Pa, peak30, 1e-7 * peak30);
}

TEST(RailEndContact, AnOpenGapLiftsThePeakAtARailEndsEdge) {
  Case c(30.0, 0.006);
  const RailEndCrossing crossing = rail_end_crossing(c.joint, c.wheel, c.settings, kLoad, 31);
  const RailEndStep& peak = crossing.steps[crossing.peak_step];
  const RailEndGap& grid = crossing.peak_gap;
  // The peak's distance from the nearer cut face, normal to the cut.
  const double to_edge = std::min(std::abs(peak.x_at_max_m - cut_x_m(c.joint, peak.y_at_max_m, 0)),
                                  std::abs(peak.x_at_max_m - cut_x_m(c.joint, peak.y_at_max_m, 1))) *
                         std::sin(c.joint.theta_rad);
  std::printf("initial %.3f GPa, peak %.3f GPa at (%.2f, %.2f) mm, %.3f mm from a cut face (cells %.3f x %.3f mm)\n",
              1e-9 * crossing.initial_max_pressure_Pa, 1e-9 * peak.max_pressure_Pa, 1e3 * peak.x_at_max_m,
              1e3 * peak.y_at_max_m, 1e3 * to_edge, 1e3 * grid.dx_m, 1e3 * grid.dy_m);
  EXPECT_GT(peak.max_pressure_Pa, 1.2 * crossing.initial_max_pressure_Pa);
  // In the row of cells along the edge: within one cell diagonal of the face.
  EXPECT_LE(to_edge, std::hypot(grid.dx_m, grid.dy_m));
}

// A load that changes with the wheel's position (a force run's N(x)): each
// step solves under the load there, which the two rail ends carry between
// them, and a step where the wheel is in flight (N = 0) has no contact.
TEST(RailEndContact, ALoadHistoryIsTheLoadOfEachStep) {
  Case c(30.0, 0.006);
  // A made-up history: P0 before the cut, a pulse of 2 P0 over the gap and
  // a flight (0) for a moment after it; the grid sized for P0.
  const double cut = cut_x_m(c.joint, 0.0, 0);
  const auto load = [cut](double x) {
    const double s = (x - cut) / 0.004;
    if (s > 1.0 && s < 2.0) return 0.0;
    return kLoad * (1.0 + std::exp(-s * s));
  };
  const RailEndCrossing crossing = rail_end_crossing(c.joint, c.wheel, c.settings, load, kLoad, 31);
  int flights = 0;
  for (const RailEndStep& s : crossing.steps) {
    EXPECT_EQ(s.normal_force_N, load(s.x_wheel_m));
    if (s.normal_force_N == 0.0) {
      ++flights;
      EXPECT_EQ(s.contact_area_m2, 0.0);
      EXPECT_EQ(s.max_pressure_Pa, 0.0);
    } else {
      // As under a constant load: the solver holds it to rounding.
      EXPECT_NEAR(s.force_incoming_N + s.force_outgoing_N, s.normal_force_N, 1e-10 * s.normal_force_N);
    }
    EXPECT_TRUE(s.converged);
  }
  EXPECT_GT(flights, 0);  // the history's flight falls on some steps
}

}  // namespace
}  // namespace railjoint
