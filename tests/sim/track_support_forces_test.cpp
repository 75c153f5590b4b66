// The lumped track's rail-seat and ballast forces (sim/track_support_forces.h):
// by hand on built states, and in a force run's static approach, where the
// rail seat carries P0 and the rail's weight.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "sim/crossing_model.h"
#include "sim/setting_checks.h"
#include "sim/simulate_crossing.h"
#include "sim/force_peaks.h"
#include "sim/track_support_forces.h"
#include "tests/sim/force_scenes.h"

namespace railjoint {
namespace {

// The gravity P0 is made with: 112.5 kN + 750 kg x 9.81 = 119,857.5 N (README).
constexpr double kG = 9.81;

// By hand on the default lumped track (pad 200 MN/m, 28 kN s/m; sleeper
// 140 kg; ballast 40 MN/m, 47 kN s/m; rail 36.12 kg): a static state under
// P0 = 119,857.5 N (rail -P0 (1/k_p + 1/k_b), sleeper -P0 / k_b) and then a
// step of 1e-5 s in which the rail drops 1 um more and the sleeper 0.5 um:
// pad 200e6 x (P0 / 200e6 + 0.5e-6) + 28e3 x (-0.05 + 0.1) = P0 + 100 + 1400
// N, ballast 40e6 x (P0 / 40e6 + 0.5e-6) + 47e3 x 0.05 = P0 + 20 + 2350 N,
// each with its weights: m_r g = 354.34 N, (m_r + m_s) g = 1727.74 N.
TEST(TrackSupportForces, ByHandOnBuiltStates) {
  const LumpedTrackSettings track;
  const double p0_N = 119857.5;
  const TrackState start{-p0_N * (1.0 / 200e6 + 1.0 / 40e6), -p0_N / 40e6, 0.0};
  const TrackState later{start.rail_z_m - 1e-6, start.sleeper_z_m - 0.5e-6, 0.0};
  const TrackSupportForces f = lumped_track_support_forces({0.0, 1e-5}, {start, later}, track, kG);
  const double rail_weight_N = 36.12 * kG, track_weight_N = (36.12 + 140.0) * kG;
  EXPECT_NEAR(f.rail_seat_N[0], p0_N + rail_weight_N, 1e-9 * p0_N);
  EXPECT_NEAR(f.ballast_N[0], p0_N + track_weight_N, 1e-9 * p0_N);
  // The rate terms divide um by 1e-5 s: round-off 1e-16 m / 1e-5 s x 5e4 N s/m ~ 1e-6 N.
  EXPECT_NEAR(f.rail_seat_N[1], p0_N + 100.0 + 1400.0 + rail_weight_N, 1e-5);
  EXPECT_NEAR(f.ballast_N[1], p0_N + 20.0 + 2350.0 + track_weight_N, 1e-5);
}

// A force run on the lumped track starts in its static state on the
// incoming slope: until the wheel nears the joint the rail seat carries P0
// (the springs' share, exact to round-off: the static state is set up to
// 8e-13) plus the rail's weight m_r g, to 1e-9; the ballast P0 + (m_r + m_s) g.
// The force run both tests below read: the default lumped track, a thin
// disc on the centre line over a square joint at 30 m/s.
SimulationResult square_joint_at_30_m_per_s() {
  SimSettings settings;
  ElasticCrossingSettings& e = settings.make_inertial().contact.emplace<ElasticCrossingSettings>();
  e.track.emplace();
  JointParams joint;
  joint.theta_rad = std::acos(0.0);
  WheelParams wheel;
  wheel.lateral_m = 0.0;
  wheel.speed_m_per_s = 30.0;
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, settings));
  return simulate_crossing(joint, wheel, settings);
}

TEST(TrackSupportForces, TheRailSeatCarriesP0AndTheRailsWeightBeforeTheJoint) {
  const SimulationResult r = square_joint_at_30_m_per_s();
  ASSERT_TRUE(r.inertial() && r.inertial()->forces && r.inertial()->forces->support);
  const ForceOutcome& f = *r.inertial()->forces;
  const TrackSupportOutcome& s = *f.support;
  const double p0_N = f.static_N;
  const double expected_seat_N = p0_N + 36.12 * kG;
  const double expected_ballast_N = p0_N + (36.12 + 140.0) * kG;
  double worst_seat = 0.0, worst_ballast = 0.0;
  std::size_t checked = 0;
  for (std::size_t k = 0; k < r.trajectory.samples.size(); ++k) {
    if (r.trajectory.samples[k].centre_m.x() > r.prediction().impact_wheel_x_m - 0.02) break;
    worst_seat = std::max(worst_seat, std::abs(s.rail_seat_N[k] / expected_seat_N - 1.0));
    worst_ballast = std::max(worst_ballast, std::abs(s.ballast_N[k] / expected_ballast_N - 1.0));
    ++checked;
  }
  std::printf("%zu approach steps: rail seat off P0 + m_r g by %.3g, ballast off P0 + (m_r + m_s) g by %.3g; "
              "peaks: seat %.1f N, ballast %.1f N, P2 at the seat %.1f N (contact P2 %.1f N)\n",
              checked, worst_seat, worst_ballast, s.rail_seat_peak_N, s.ballast_peak_N, s.p2_rail_seat_N,
              f.p2->force_N);
  ASSERT_GT(checked, 10u);
  EXPECT_LT(worst_seat, 1e-9);
  EXPECT_LT(worst_ballast, 1e-9);
  EXPECT_NEAR(s.rail_seat_static_N, expected_seat_N, 1e-9 * expected_seat_N);
  // The rail seat is loaded through the pad after the contact: its peak
  // above its static load, and its P2 above P0 + m_r g.
  EXPECT_GT(s.rail_seat_peak_N, expected_seat_N);
  EXPECT_GT(s.p2_rail_seat_N, expected_seat_N);
}

// The rail seat's force history against the independent planar model of
// tests/sim/lumped_track_reference.h (wheel, rail and sleeper masses, Hertz
// on the two rail ends' half-planes, Dormand-Prince at 1e-11), whose pad
// force is k_p (z_s - z_r) + c_p (w_s - w_r) with the exact velocities: the
// peak and the low-passed P2 within 1 % (the contact force agrees within
// 0.24 % of P1; the rates here are backward differences of the recorded
// displacements, first order in the step: c_p x a dt / 2 ~ 28e3 x 1e3 x
// 2e-6 = 56 N at P1's rail acceleration). Square joint, 30 m/s, thin disc.
TEST(TrackSupportForces, TheRailSeatAgreesWithTheReferenceModelWithinOnePercent) {
  const SimulationResult r = square_joint_at_30_m_per_s();
  ASSERT_TRUE(r.inertial() && r.inertial()->forces && r.inertial()->forces->support);
  const TrackSupportOutcome& s = *r.inertial()->forces->support;
  const CrossingModel& m = *r.model;
  // The track state at sample k is the one at its own time (the step's end).
  std::vector<double> times;
  for (const WheelSample& sample : r.trajectory.samples) times.push_back(sample.time_s);
  const testing_reference::ReferenceHistory h = lumped_reference_history(m, times);
  const LumpedTrackSettings track;
  std::vector<double> reference_seat_N;
  for (const double pad_N : h.pad_N) reference_seat_N.push_back(pad_N + track.rail_mass_kg * kG);
  const ForcePeaks reference =
      pick_force_peaks(times, reference_seat_N, s.rail_seat_static_N, kP2CutoffFrequency_Hz,
                       r.inertial()->forces->p2->mode_period_s);
  const double reference_peak_N = *std::max_element(reference_seat_N.begin(), reference_seat_N.end());
  std::printf("rail seat: peak %.1f N (reference %.1f N, %+.3f %%), P2 %.1f N (reference %.1f N, %+.3f %%)\n",
              s.rail_seat_peak_N, reference_peak_N, 100.0 * (s.rail_seat_peak_N / reference_peak_N - 1.0),
              s.p2_rail_seat_N, reference.p2_N, 100.0 * (s.p2_rail_seat_N / reference.p2_N - 1.0));
  EXPECT_NEAR(s.rail_seat_peak_N, reference_peak_N, 0.01 * reference_peak_N);
  EXPECT_NEAR(s.p2_rail_seat_N, reference.p2_N, 0.01 * reference.p2_N);
}

}  // namespace
}  // namespace railjoint
