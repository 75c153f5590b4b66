// Force runs on real geometry where Hertz's law has no curvature to work
// with: a wheel whose contact leaves the head's top for its gauge corner,
// and a measured head with a cusp. Neither may give a NaN: the run either
// refuses by key or bears the contact on a law it names in the report
// (force_contact_geometry.h: an edge takes the empirical constant).

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "models/profile_curve.h"
#include "sim/setting_checks.h"
#include "sim/simulate_crossing.h"
#include "support/input_error.h"

namespace railjoint {
namespace {

SimSettings hertz_settings() {
  SimSettings s;
  s.make_inertial().contact.emplace<ElasticCrossingSettings>();
  return s;
}

SimulationResult force_run(JointParams joint, const WheelParams& wheel) {
  const SimSettings settings = hertz_settings();
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, settings));
  return simulate_crossing(joint, wheel, settings);
}

void expect_finite_forces(const char* label, const SimulationResult& r) {
  ASSERT_TRUE(r.inertial() && r.inertial()->forces);
  const ForceOutcome& f = *r.inertial()->forces;
  const HertzAtPeak& p0 = f.hertz_patches.at_p0;
  std::printf("%s: law at P0 %s, y %.4f mm, G %.4g; P1 %.1f N\n", label, p0.law.c_str(), p0.contact_y_m * 1e3,
              p0.hertz_constant_m_per_N2_3, f.p1_N);
  for (const double force : f.contact_force_N) ASSERT_TRUE(std::isfinite(force));
  EXPECT_TRUE(std::isfinite(f.p1_N));
  for (const HertzAtPeak* h : {&f.hertz_patches.at_p0, &f.hertz_patches.at_p1}) {
    EXPECT_FALSE(h->law.empty());
    EXPECT_TRUE(std::isfinite(h->hertz_constant_m_per_N2_3) && h->hertz_constant_m_per_N2_3 > 0.0);
    if (h->patch) {
      EXPECT_TRUE(std::isfinite(h->patch->semi_axis_x_m) && std::isfinite(h->patch->semi_axis_y_m));
    }
  }
}

// A flat 40 mm head under a 30 mm wheel whose tread widens outwards (conicity
// -0.05) with its plane at y = 25 mm: the tread spans 10-40 mm, the head
// ends at 20 mm, and the largest radius over the head is at its edge, so
// the wheel bears on the gauge corner (the head's top meets its side: no
// curvature across). By hand: the contact sits at y = 20 mm, and an edge
// takes the empirical constant 3.86e-8 R^-0.115 (force_contact_geometry.h).
TEST(RealGeometryBadInput, AContactOnTheGaugeCornerBearsOnTheEdgesLaw) {
  JointParams joint;
  joint.theta_rad = 3.14159265358979323846 / 2.0;
  WheelParams wheel;
  wheel.width_m = 0.03;
  wheel.lateral_m = 0.025;
  wheel.conicity = -0.05;
  wheel.speed_m_per_s = 30.0;
  const SimulationResult r = force_run(joint, wheel);
  expect_finite_forces("gauge corner", r);
  const HertzAtPeak& p0 = r.inertial()->forces->hertz_patches.at_p0;
  EXPECT_NEAR(p0.contact_y_m, joint.half_width_m, 1e-9);
  EXPECT_EQ(p0.law, "empirical");
  EXPECT_NEAR(p0.hertz_constant_m_per_N2_3, 3.86e-8 * std::pow(wheel.radius_m, -0.115), 1e-15);
  // Wholly off the head (the tread starts at 21 mm): refused by the key typed.
  wheel.lateral_m = 0.036;
  try {
    force_run(joint, wheel);
    ADD_FAILURE() << "a wheel off the head ran";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "wheel.y") << e.what();
  }
}

// A measured head whose points make a tent, z = -0.2 |y| (a ridge, 11 deg
// each side), every 0.5 mm: its apex is a cusp with no curvature of its
// own. The cubic spline through the points (models/profile_curve.h) has a
// continuous curvature, so the kink becomes an arc about one spacing wide
// (its y'' at the apex about -0.4 x 6 / (3.46 h): radius ~ 0.7 mm, ringing
// away by -0.27 a knot): Hertz either takes that arc or, where
// the ellipse is too slender to be one (b/a < 1e-6), the empirical law.
// Either way the run names its law and no force is NaN.
TEST(RealGeometryBadInput, AMeasuredHeadWithACuspGivesNoNaN) {
  std::vector<double> y, z;
  for (int i = -40; i <= 40; ++i) {
    y.push_back(0.0005 * i);
    z.push_back(-0.2 * std::abs(0.0005 * i));
  }
  JointParams joint;
  joint.theta_rad = 3.14159265358979323846 / 2.0;
  joint.rail_profile = RailProfile::measured;
  joint.measured_head = std::make_shared<const ProfileCurve>(y, z, "tent", 0.0);
  WheelParams wheel;
  wheel.width_m = 0.02;
  wheel.lateral_m = 0.0;
  wheel.speed_m_per_s = 30.0;
  const SimulationResult r = force_run(joint, wheel);
  expect_finite_forces("cusp", r);
  const HertzAtPeak& p0 = r.inertial()->forces->hertz_patches.at_p0;
  EXPECT_NEAR(p0.contact_y_m, 0.0, 1e-6);
}

}  // namespace
}  // namespace railjoint
