// The impulse estimator on hand-made trajectories, where the answer is known
// exactly: no Bullet involved.

#include "sim/momentum_jump.h"

#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

namespace railjoint {
namespace {

constexpr double kMass_kg = 750.0;

// zdot(t) = a_before (t - t0) + c_before for t < t0, a_after (t - t0) +
// c_after after, recorded every dt the way Bullet's step records it: forces
// applied, contacts of the configuration at the step's start solved, then
// the wheel moved, so a sample's velocity is zdot at the start of the step
// that ended at it. t0 on a sample time: the next step carries the jump,
// applied at its start t0.
Trajectory piecewise_linear(double t0, double c_before, double a_before, double c_after, double a_after, double dt,
                            int samples) {
  Trajectory trajectory;
  for (int k = 0; k < samples; ++k) {
    WheelSample s;
    s.time_s = k * dt;
    s.centre_m.x() = 50.0 * s.time_s;
    const double step_start = s.time_s - dt;
    s.velocity_time_s = step_start;
    s.velocity_m_per_s.z() =
        step_start < t0 ? c_before + a_before * (step_start - t0) : c_after + a_after * (step_start - t0);
    trajectory.samples.push_back(s);
  }
  return trajectory;
}

JumpDetection detection() {
  JumpDetection d;
  d.mass_kg = kMass_kg;
  d.vertical_force_N = 0.0;
  d.impact_acceleration_m_per_s2 = 1e5;
  d.smooth_acceleration_m_per_s2 = 2e4;
  return d;
}

TEST(MomentumJump, PlateausGiveTheJumpTimesTheMass) {
  // zdot from -0.75 to +0.75 m/s: Delta p = 750 kg * 1.5 m/s = 1125 N s (scenario 1 at 50 m/s, beta 0.03).
  const Trajectory t = piecewise_linear(50e-6, -0.75, 0.0, 0.75, 0.0, 1e-6, 101);
  const auto jumps = find_momentum_jumps(t, detection());
  ASSERT_EQ(jumps.size(), 1u);
  std::cout << "jump " << jumps[0].jump_Ns << " N s at " << jumps[0].time_s << " s\n";
  EXPECT_NEAR(jumps[0].jump_Ns, 1125.0, 1e-9);  // exact fit of constant data, round-off only
  // The jump is in the step from 50 us to 51 us, applied at its start (no
  // contacts recorded, so no overlap to date it earlier).
  EXPECT_NEAR(jumps[0].time_s, 50e-6, 1e-15);
  EXPECT_NEAR(jumps[0].wheel_x_m, 50.0 * 50e-6, 1e-15);
}

TEST(MomentumJump, SlopedSidesAreExtrapolatedToTheImpactInstant) {
  // After a scenario-2 impact zdot falls at v^2/R ~ 5263 m/s^2 (pivot). A
  // plateau estimate taken 10 us later would be 0.053 m/s (39 N s) low; the
  // linear extrapolation of both sides recovers M (0.9 - (-0.75)) exactly.
  const double t0 = 50e-6;
  const Trajectory t = piecewise_linear(t0, -0.75, 0.0, 0.9, -5263.0, 1e-6, 101);
  const auto jumps = find_momentum_jumps(t, detection());
  ASSERT_EQ(jumps.size(), 1u);
  std::cout << "jump " << jumps[0].jump_Ns << " N s, zdot+ " << jumps[0].zdot_after_m_per_s << " m/s\n";
  EXPECT_NEAR(jumps[0].zdot_after_m_per_s, 0.9, 1e-9);
  EXPECT_NEAR(jumps[0].jump_Ns, kMass_kg * 1.65, 1e-6);
}

TEST(MomentumJump, UnsolvedStepsOfAPivotAreLeftOutOfTheFit) {
  // Before a landing the wheel pivots about a corner: zdot falls at
  // v^2/R = 5263 m/s^2 (50 m/s, R 0.475 m), then the landing on a level rail
  // stops it (zdot+ = 0): Delta p = M * 0.75 m/s = 562.5 N s. On a fast
  // pivot every other step ends with the contact open by the arc's rise
  // (v dt)^2 / 2R and goes unsolved: the wheel falls freely under the load
  // (2 M v^2 / R here), 5263 m/s^2 * 1e-6 s = 5.3e-3 m/s faster than the
  // arc. The solved steps carry the arc's zdot; a fit through all of them
  // would be off by half of that, 2.6e-3 m/s or 2 N s (0.35 %).
  const double t0 = 50e-6;
  Trajectory t = piecewise_linear(t0, -0.75, -5263.0, 0.0, 0.0, 1e-6, 101);
  for (std::size_t k = 1; k < t.samples.size(); ++k) {
    ContactSample c;
    c.normal = Eigen::Vector3d::UnitZ();
    c.rail_index = t.samples[k].time_s <= t0 + 1e-12 ? 0 : 1;
    const bool unsolved_pivot_step = c.rail_index == 0 && k % 2 == 1;
    c.normal_impulse_Ns = unsolved_pivot_step ? 0.0 : 1.0;
    if (unsolved_pivot_step) t.samples[k].velocity_m_per_s.z() -= 5263.0 * 1e-6;
    t.samples[k].contacts.push_back(c);
  }
  const auto jumps = find_momentum_jumps(t, detection());
  ASSERT_EQ(jumps.size(), 1u);
  std::cout << "jump " << jumps[0].jump_Ns << " N s, zdot- " << jumps[0].zdot_before_m_per_s << " m/s\n";
  // The solved steps lie on the line exactly: round-off only.
  EXPECT_NEAR(jumps[0].zdot_before_m_per_s, -0.75, 1e-9);
  EXPECT_NEAR(jumps[0].jump_Ns, kMass_kg * 0.75, 1e-6);
}

TEST(MomentumJump, AHeldStepCutShortBeforeALandingIsNoPartOfIt) {
  // The pivot before a landing, zdot falling at v^2/R = 5263 m/s^2 (50 m/s,
  // R 0.475 m), every step on the incoming rail (rail 0) dated at its start;
  // the last one cut short to 1e-7 s to end at the landing's first touch,
  // t0 = 50.1 us, and held on the pivot: its velocity is the tangent at its
  // start, 50 us, a whole 1e-6 s of turning after the step before's. The
  // landing on a level outgoing rail (rail 1) stops zdot: Delta p =
  // M * 0.75 m/s = 562.5 N s at t0. Over its own 1e-7 s the held step reads
  // as 52,630 m/s^2, above the smooth bound (2e4); over the 1e-6 s between
  // its velocity's instant and the step before's, as the pivot's 5263.
  const double a = -5263.0, t0 = 50.1e-6, dt = 1e-6;
  const auto pivot_zdot = [&](double t) { return -0.75 + a * (t - t0); };
  Trajectory t;
  const auto add = [&](double time, double velocity_time, double zdot, int rail) {
    WheelSample s;
    s.time_s = time;
    s.velocity_time_s = velocity_time;
    s.centre_m.x() = 50.0 * time;
    s.velocity_m_per_s.z() = zdot;
    ContactSample c;
    c.normal = Eigen::Vector3d::UnitZ();
    c.rail_index = rail;
    c.normal_impulse_Ns = 1.0;
    s.contacts.push_back(c);
    t.samples.push_back(s);
  };
  for (int k = 0; k <= 50; ++k) add(k * dt, (k - 1) * dt, pivot_zdot((k - 1) * dt), 0);
  add(t0, 50 * dt, pivot_zdot(50 * dt), 0);
  for (int k = 1; k <= 30; ++k) add(t0 + k * dt, t0 + (k - 1) * dt, 0.0, 1);
  const auto jumps = find_momentum_jumps(t, detection());
  ASSERT_EQ(jumps.size(), 1u);
  std::cout << "jump " << jumps[0].jump_Ns << " N s at " << jumps[0].time_s << " s, samples " << jumps[0].first_sample
            << "-" << jumps[0].last_sample << "\n";
  EXPECT_EQ(jumps[0].first_sample, 52u);  // the landing step, not the held one before it
  EXPECT_NEAR(jumps[0].time_s, t0, 1e-15);
  // Every side sample on its line: round-off only. Taken into the landing,
  // the held step moved the instant back to 50 us and the jump down by
  // M |a| 1e-7 s = 0.39 N s.
  EXPECT_NEAR(jumps[0].zdot_before_m_per_s, -0.75, 1e-9);
  EXPECT_NEAR(jumps[0].jump_Ns, kMass_kg * 0.75, 1e-6);
}

TEST(MomentumJump, SmoothMotionIsNoImpact) {
  // Free flight under a 100 kN load: 133 m/s^2 + g, far below the threshold.
  const Trajectory t = piecewise_linear(1.0, 0.3, -143.0, 0.0, 0.0, 1e-6, 200);
  EXPECT_TRUE(find_momentum_jumps(t, detection()).empty());
}

TEST(MomentumJump, AFlickeringContactIsNoImpact) {
  // The contact opens for one 50 us step under a 7.9 MN load (2 M v^2 / R
  // at 50 m/s): the wheel gains 0.53 m/s downwards, the next step stops it
  // again. Both steps are far above the impact acceleration; net jump 0.
  Trajectory t = piecewise_linear(1.0, -0.75, 0.0, 0.0, 0.0, 1e-6, 101);
  t.samples[40].velocity_m_per_s.z() -= 0.53;
  EXPECT_TRUE(find_momentum_jumps(t, detection()).empty());
}

TEST(MomentumJump, OverlapDatesTheImpactInsideItsStep) {
  // The struck contact was found 2 um deeper than the touching gap, closing
  // at 2 m/s: it touched 1 us before the step that carried the impulse.
  Trajectory t = piecewise_linear(50e-6, -0.75, 0.0, 0.75, 0.0, 1e-6, 101);
  ContactSample strike;
  strike.normal = Eigen::Vector3d(-std::sqrt(1.0 - 0.75 * 0.75), 0.0, 0.75);
  strike.distance_m = -6e-6;
  strike.normal_impulse_Ns = 1500.0;
  t.samples[51].contacts.push_back(strike);
  for (auto& s : t.samples) s.velocity_m_per_s.x() = 2.0 / std::sqrt(1.0 - 0.75 * 0.75) / 1.0;
  // closing speed = -(v . n) = vx * sqrt(1 - 0.5625) - zdot * 0.75 with zdot = -0.75 before.
  const double closing = t.samples[50].velocity_m_per_s.x() * std::sqrt(1.0 - 0.5625) + 0.75 * 0.75;
  JumpDetection d = detection();
  d.touch_distance_m = -4e-6;
  const auto jumps = find_momentum_jumps(t, d);
  ASSERT_EQ(jumps.size(), 1u);
  EXPECT_NEAR(jumps[0].time_s, 50e-6 - 2e-6 / closing, 1e-15);
}

TEST(MomentumJump, TwoImpactsAreSeparate) {
  Trajectory t = piecewise_linear(30e-6, -0.75, 0.0, 0.75, 0.0, 1e-6, 101);
  for (auto& s : t.samples) {
    if (s.time_s > 70.5e-6) s.velocity_m_per_s.z() -= 0.5;  // a landing 41 us later: -375 N s
  }
  const auto jumps = find_momentum_jumps(t, detection());
  ASSERT_EQ(jumps.size(), 2u);
  EXPECT_NEAR(jumps[0].jump_Ns, 1125.0, 1e-9);
  EXPECT_NEAR(jumps[1].jump_Ns, -375.0, 1e-9);
}

TEST(MomentumJump, ContactImpulsesAddUpWithTheLoadTakenOut) {
  // One impact step carrying 1125 N s of jump plus the steady load F dt:
  // the contact sum is 1125 + |F| dt and the cross-check removes |F| dt again.
  Trajectory t = piecewise_linear(50e-6, -0.75, 0.0, 0.75, 0.0, 1e-6, 101);
  const double load_N = 1e5;
  for (auto& s : t.samples) {
    ContactSample c;
    c.normal = Eigen::Vector3d::UnitZ();
    c.distance_m = -1e-5;
    c.normal_impulse_Ns = load_N * 1e-6;
    c.rail_index = 0;
    s.contacts.push_back(c);
  }
  ContactSample strike;
  strike.normal = Eigen::Vector3d(-0.6, 0.0, 0.8);
  strike.normal_impulse_Ns = 1125.0 / 0.8;
  strike.rail_index = 1;
  strike.point_on_rail_m = Eigen::Vector3d(0.02, 0.015, 0.0);
  t.samples[51].contacts.push_back(strike);
  JumpDetection d = detection();
  d.vertical_force_N = -load_N;
  const auto jumps = find_momentum_jumps(t, d);
  ASSERT_EQ(jumps.size(), 1u);
  EXPECT_NEAR(jumps[0].from_contacts_Ns, 1125.0, 1e-9);
  EXPECT_EQ(jumps[0].struck_rail, 1);
  EXPECT_NEAR(jumps[0].struck_point_m.x(), 0.02, 1e-15);
  ASSERT_TRUE(jumps[0].left_point_m.allFinite());  // the wheel left rail 0
}

TEST(MomentumJump, ACoarseFixedStepStillCarriesAnImpact) {
  // Scenario 1 at 50 m/s under the 100 kN preload, fixed 1e-4 s steps: the
  // whole 1.5 m/s jump falls into one step, a mean acceleration of
  // 1.5e4 m/s^2. The smooth bound is v^2/R + |F|/M = 5263 + 133 = 5396 m/s^2,
  // so the fine-step criterion (20x = 1.08e5) misses it; one step changing
  // zdot by 1.5 m/s >= 0.01 v = 0.5 m/s at more than 1.5x the bound
  // (8094 m/s^2) is an impact whatever the step. Constant sides: exact fit.
  const JumpDetection d = jump_detection_for(kMass_kg, 50.0, 0.475, -1e5, 0.0);
  const Trajectory t = piecewise_linear(20e-4, -0.75, 0.0, 0.75, 0.0, 1e-4, 41);
  ASSERT_LT(1.5 / 1e-4, d.impact_acceleration_m_per_s2);
  const auto jumps = find_momentum_jumps(t, d);
  ASSERT_EQ(jumps.size(), 1u);
  EXPECT_NEAR(jumps[0].jump_Ns, 1125.0, 1e-9);
  EXPECT_NEAR(jumps[0].time_s, 20e-4, 1e-15);
}

TEST(MomentumJump, ACoarseStepOfSmoothPivotIsNoImpact) {
  // Pivoting about a corner at 50 m/s: zdot falls at v^2/R = 5263 m/s^2,
  // 1.05 m/s per 2e-4 s step (more than 0.01 v) but below 1.5x the smooth bound.
  const JumpDetection d = jump_detection_for(kMass_kg, 50.0, 0.475, -1e5, 0.0);
  const Trajectory t = piecewise_linear(1.0, 0.9, -5263.0, 0.0, 0.0, 2e-4, 30);
  EXPECT_TRUE(find_momentum_jumps(t, d).empty());
}

TEST(MomentumJump, ASmallLandingInOneStepIsAnImpactASmoothPivotIsNot) {
  // A 1.1 cm cylinder landing at 11.6 m/s after a scenario-2 flight (random
  // inertial scene cylinder_105): 5.43 N s, located, in one 1e-6 s step,
  // 7.2e-3 m/s at 7240 m/s^2. Smooth motion there accelerates at most at
  // v^2/R + W/M = 299 + 160 = 459 m/s^2 (R 0.45 m, W 119.9 kN): it is
  // sixteen times that, and an impact. A pivot at v^2/R for 100 steps is not.
  const JumpDetection d = jump_detection_for(kMass_kg, 11.6, 0.45, -119857.0, 0.0);
  Trajectory landing = piecewise_linear(50e-6, -0.0072, 0.0, 0.0, 0.0, 1e-6, 101);
  const auto jumps = find_momentum_jumps(landing, d);
  ASSERT_EQ(jumps.size(), 1u);
  EXPECT_NEAR(jumps[0].jump_Ns, kMass_kg * 0.0072, 1e-9);
  const Trajectory pivot = piecewise_linear(1.0, 0.3, -11.6 * 11.6 / 0.45, 0.0, 0.0, 1e-6, 101);
  EXPECT_TRUE(find_momentum_jumps(pivot, d).empty());
}

TEST(MomentumJump, ALandingBelowTheFastStepsFloorSoonAfterAStrikeIsFound) {
  // 60E1 scene 21 of the real-geometry inertial study's seed 1, by hand:
  // 46.3 m/s, W 119,850 N on 750 kg (g_W = 159.8 m/s^2). The strike turns
  // zdot from -0.7745 to +0.7745 m/s in the step from 40 us (1161.75 N s);
  // the wheel flies 20 steps, zdot falling at g_W, no contact solved; the
  // step from 60 us lands it back on rail 1's slope, zdot = 0.7745 m/s:
  // Delta p = M g_W 20 us = 750 * 159.8 * 2e-5 = 2.397 N s, below the fast
  // steps' floor 1e-4 M v = 3.47 N s, and 20 us after the strike, inside
  // the merge window (2e-5 s from the strike's last sample, 41 us, to the
  // landing's first step's start, 60 us: 19 us).
  const double g_W = 159.8, dt = 1e-6;
  const JumpDetection d = jump_detection_for(kMass_kg, 46.3, 0.46, -kMass_kg * g_W, 0.0);
  Trajectory t;
  for (int k = 0; k <= 90; ++k) {
    WheelSample s;
    s.time_s = k * dt;
    s.velocity_time_s = (k - 1) * dt;
    s.centre_m.x() = 46.3 * s.time_s;
    ContactSample c;
    c.normal = Eigen::Vector3d::UnitZ();
    c.rail_index = k <= 40 ? 0 : 1;
    c.normal_impulse_Ns = (k <= 41 || k >= 61) ? 0.12 : 0.0;  // solved on a rail, open in flight
    s.contacts.push_back(c);
    const double flight_s = s.velocity_time_s - 40e-6;
    s.velocity_m_per_s.z() = k <= 40 ? -0.7745 : (k <= 60 ? 0.7745 - g_W * flight_s : 0.7745);
    t.samples.push_back(s);
  }
  const auto jumps = find_momentum_jumps(t, d);
  ASSERT_EQ(jumps.size(), 2u);
  std::cout << "strike " << jumps[0].jump_Ns << " N s, landing " << jumps[1].jump_Ns << " N s at " << jumps[1].time_s
            << " s\n";
  // Every side on its line (constant or the flight's): round-off only.
  EXPECT_NEAR(jumps[0].jump_Ns, kMass_kg * 2 * 0.7745, 1e-9);
  EXPECT_NEAR(jumps[1].jump_Ns, kMass_kg * g_W * 20e-6, 1e-9);
  EXPECT_NEAR(jumps[1].time_s, 60e-6, 1e-15);
}

TEST(MomentumJump, DetectionSeparatesSmoothMotionFromTheThesisJump) {
  // v 10 m/s, R 0.5 m, a load of -7.5 kN on 750 kg. Smooth motion accelerates
  // at most by v^2/R + |F|/M = 100 / 0.5 + 7500 / 750 = 210 m/s^2 (a pivot
  // about a corner under the load): no bound may flag it.
  // The smallest jump that must be found: the thesis's scenario 1 with
  // beta = 0.03 at this speed, 2 M v tan(beta/2) = 225.0 N s, a velocity change
  // of 0.300 m/s. Resolved over ten 1e-6 s steps it accelerates at
  // 0.3 / 1e-5 = 3e4 m/s^2; swallowed by one 1e-4 s coarse step, at 3e3 m/s^2.
  const JumpDetection d = jump_detection_for(kMass_kg, 10.0, 0.5, -7500.0, -4e-6);
  const double smooth_m_per_s2 = 210.0;
  const double thesis_dv_m_per_s = 2.0 * 10.0 * std::tan(0.015);
  std::cout << "impact " << d.impact_acceleration_m_per_s2 << ", smooth " << d.smooth_acceleration_m_per_s2
            << ", coarse " << d.coarse_jump_m_per_s << " m/s at " << d.coarse_acceleration_m_per_s2
            << " m/s^2, min jump " << d.min_jump_Ns << " N s; thesis dv " << thesis_dv_m_per_s << " m/s\n";
  EXPECT_GT(d.smooth_acceleration_m_per_s2, smooth_m_per_s2);
  EXPECT_GT(d.impact_acceleration_m_per_s2, d.smooth_acceleration_m_per_s2);
  EXPECT_GT(d.coarse_acceleration_m_per_s2, smooth_m_per_s2);
  EXPECT_LT(d.impact_acceleration_m_per_s2, thesis_dv_m_per_s / 1e-5);
  EXPECT_LE(d.coarse_jump_m_per_s, thesis_dv_m_per_s);
  EXPECT_LT(d.coarse_acceleration_m_per_s2, thesis_dv_m_per_s / 1e-4);
  // A flickering contact's kick must not count, the jump must: the floor sits
  // far below 1 % of the jump.
  EXPECT_GT(d.min_jump_Ns, 0.0);
  EXPECT_LT(d.min_jump_Ns, 0.01 * kMass_kg * thesis_dv_m_per_s);
  EXPECT_DOUBLE_EQ(d.touch_distance_m, -4e-6);
}

TEST(MomentumJump, LiftoffNeedsSustainedOpenContacts) {
  Trajectory t = piecewise_linear(1.0, 0.0, 0.0, 0.0, 0.0, 1e-6, 20);
  for (std::size_t k = 0; k < t.samples.size(); ++k) {
    ContactSample c;
    c.distance_m = k < 10 ? -1e-5 : (k == 10 ? 1e-6 : (k == 11 ? -1e-6 : 2e-6));
    t.samples[k].contacts.push_back(c);
  }
  // Sample 10 opens for one sample only; from 12 on it stays open.
  EXPECT_NEAR(find_liftoff_time_s(t, 0, 3), 12e-6, 1e-15);
  EXPECT_LT(find_liftoff_time_s(t, 0, 30), 0.0);
}

}  // namespace
}  // namespace railjoint
