// Contact and flight phases found in hand-made trajectories (sim/contact_phases.h).

#include "sim/contact_phases.h"

#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

namespace railjoint {
namespace {

// A wheel at 10 m/s sampled every 10 us: in contact (carrying 1e5 N) until
// t = 1 ms, in flight from 1 ms to 3 ms on the parabola
// z = w0 (t - 1 ms) - g (t - 1 ms)^2 / 2 with w0 = 0.1 m/s, g = 100 m/s^2
// (back at z = 0 at 1 ms + 2 w0 / g = 3 ms), then in contact again. The
// reference path is z = 0.
constexpr double kDt = 1e-5;

WheelSample sample(double t, double z, bool contact) {
  WheelSample w;
  w.time_s = t;
  w.centre_m = Eigen::Vector3d(10.0 * t, 0.0, z);
  if (contact) {
    ContactSample c;
    c.normal_impulse_Ns = 1e5 * kDt;
    w.contacts.push_back(c);
  }
  return w;
}

Trajectory one_flight() {
  Trajectory t;
  for (int k = 0; k <= 500; ++k) {
    const double time = k * kDt;
    const bool flying = time > 1e-3 + 1e-12 && time < 3e-3 - 1e-12;
    const double tf = time - 1e-3;
    t.samples.push_back(sample(time, flying ? 0.1 * tf - 50.0 * tf * tf : 0.0, !flying));
  }
  return t;
}

TEST(ContactPhases, FindsTheFlightAndItsApex) {
  const ContactPhaseAnalysis a = analyse_contact_phases(one_flight(), [](double) { return 0.0; }, PhaseDetection{});
  ASSERT_EQ(a.flights.size(), 1u);
  const Flight& f = a.flights.front();
  std::cout << "lift-off " << f.liftoff_time_s << " s, landing " << f.landing_time_s << " s, apex " << f.apex_height_m
            << " m at " << f.apex_time_s << " s\n";
  // Last contact sample at 1 ms, first one again at 3 ms (sample times exact to round-off).
  EXPECT_NEAR(f.liftoff_time_s, 1e-3, 1e-12);
  EXPECT_NEAR(f.landing_time_s, 3e-3, 1e-12);
  EXPECT_NEAR(f.duration_s, 2e-3, 1e-12);
  EXPECT_TRUE(f.landed);
  // Apex w0^2 / (2 g) = 0.01 / 200 = 5e-5 m at 1 ms + w0 / g = 2 ms, a sample instant.
  EXPECT_NEAR(f.apex_height_m, 5e-5, 1e-12);
  EXPECT_NEAR(f.apex_time_s, 2e-3, 1e-12);
  EXPECT_NEAR(f.max_clearance_m, 5e-5, 1e-12);
  EXPECT_NEAR(a.max_deviation_m, 5e-5, 1e-12);
  // Contact, flight, contact, covering the run.
  ASSERT_EQ(a.phases.size(), 3u);
  EXPECT_TRUE(a.phases[0].in_contact);
  EXPECT_FALSE(a.phases[1].in_contact);
  EXPECT_TRUE(a.phases[2].in_contact);
  EXPECT_DOUBLE_EQ(a.phases.front().start_time_s, 0.0);
  EXPECT_NEAR(a.phases.back().end_time_s, 5e-3, 1e-12);
  EXPECT_FALSE(a.ended_in_flight);
  // The contact force is the impulse over the step: 1e5 N.
  EXPECT_NEAR(a.peak_force_N, 1e5, 1e-6);
}

TEST(ContactPhases, ChatterAndFlickersAreNoFlight) {
  // A contact that opens for 5 samples (50 us) while the wheel stays within
  // 1 um of the path (the rigid contact's chatter band), and one that opens
  // for a single sample: neither is a flight.
  Trajectory t;
  for (int k = 0; k <= 300; ++k) {
    const bool open = (k >= 100 && k < 105) || k == 200;
    t.samples.push_back(sample(k * kDt, open ? 1e-6 : 0.0, !open));
  }
  const ContactPhaseAnalysis a = analyse_contact_phases(t, [](double) { return 0.0; }, PhaseDetection{});
  EXPECT_TRUE(a.flights.empty());
  ASSERT_EQ(a.phases.size(), 1u);
  EXPECT_TRUE(a.phases.front().in_contact);
}

TEST(ContactPhases, RunEndingInFlight) {
  Trajectory t = one_flight();
  t.samples.resize(200);  // cut at 1.99 ms, half way through the flight
  const ContactPhaseAnalysis a = analyse_contact_phases(t, [](double) { return 0.0; }, PhaseDetection{});
  ASSERT_EQ(a.flights.size(), 1u);
  EXPECT_FALSE(a.flights.front().landed);
  EXPECT_TRUE(std::isnan(a.flights.front().landing_time_s));
  EXPECT_TRUE(a.ended_in_flight);
}

}  // namespace
}  // namespace railjoint

namespace railjoint {
namespace {

// The recorded contact force of a step is its impulse over the time it
// carried the load: the step, or the velocity's age where the solver
// weighed the contacts over it (contacts_weighed_over_velocity_age). By
// hand, a wheel held on a rail under 1e5 N: fine steps of 1 us, a step cut
// to 0.25 us that the solver weighed over its velocity's age (1 us: 0.1 N s),
// fine steps again, then a coarse 100 us step whose velocity is dated a
// fine step back (a spring's step, or a shortening step's neighbour on a
// plane: not weighed over the age, 10 N s over its own 100 us). Each reads
// 1e5 N; dating the coarse step by its velocity's age read 1e7 N.
TEST(ContactPhases, TheForceIsTheImpulseOverTheTimeItCarriedTheLoad) {
  const double force_N = 1e5;
  std::vector<WheelSample> s(1);
  s[0].velocity_time_s = -1e-6;
  double t = 0.0;
  const auto step = [&](double dt, double load_span_s, bool weighed) {
    WheelSample w;
    w.velocity_time_s = t;  // a contact acted: the velocity is its step's start's
    t += dt;
    w.time_s = t;
    w.contacts_weighed_over_velocity_age = weighed;
    ContactSample c;
    c.normal_impulse_Ns = force_N * load_span_s;
    w.contacts.push_back(c);
    s.push_back(w);
  };
  for (int k = 0; k < 3; ++k) step(1e-6, 1e-6, false);
  step(0.25e-6, 1e-6, true);   // the cut step, weighed over its velocity's age (1 us)
  step(1e-6, 1e-6, false);
  step(1e-4, 1e-4, false);     // a coarse step after a fine one
  for (std::size_t k = 1; k < s.size(); ++k) {
    const double f = vertical_contact_force_N(s, k);
    std::cout << "step " << k << ": " << s[k].time_s - s[k - 1].time_s << " s, " << f << " N\n";
    EXPECT_NEAR(f, force_N, 1e-9 * force_N) << k;
  }
}

}  // namespace
}  // namespace railjoint
