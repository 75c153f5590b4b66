// Measured profiles (models/profile_curve.h) and the general model on them:
// a measured tread of a straight cone is that cone, a measured 60E1 head
// converges on the drawn one as its points get closer.

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "general_geometry_reference.h"
#include "models/impact_prediction.h"
#include "models/parameter_checks.h"
#include "models/profile_curve.h"
#include "models/wheel_rail_envelope.h"

namespace railjoint {
namespace {

std::string message_of(const std::string& text, ProfileKind kind = ProfileKind::rail_head) {
  try {
    read_profile_csv(text, "test.csv", kind);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(ProfileCurve, ReadsPointsWithAHeaderAndComments) {
  const ProfileCurve curve = read_profile_csv("# a head\ny_m,z_m\n-0.02,-0.001\n-0.01,-0.0002\n0,0\n0.01,-0.0002\r\n0.02,-0.001\n",
                                              "test.csv", ProfileKind::rail_head);
  EXPECT_EQ(curve.y_min_m(), -0.02);
  EXPECT_EQ(curve.y_max_m(), 0.02);
  EXPECT_EQ(curve.max_value_m(), 0.0);
  EXPECT_EQ(curve.value_m(0.01), -0.0002);  // through its points
  EXPECT_EQ(curve.source(), "test.csv");
}

TEST(ProfileCurve, RefusesWhatIsNoProfile) {
  EXPECT_NE(message_of("0,0\n0.01,0\n0.02,0\n").find("at least 4 points"), std::string::npos);
  EXPECT_NE(message_of("0,0\n0.01,0\n0.01,0.001\n0.02,0\n").find("y must increase"), std::string::npos);
  EXPECT_NE(message_of("y,z\n0,0\n0.01,x\n0.02,0\n0.03,0\n").find("line 3"), std::string::npos);
  EXPECT_NE(message_of("0,0\n0.01,0,5\n0.02,0\n0.03,0\n").find("line 2"), std::string::npos);
}

// Modified Akima is exact on straight points: a tread measured off a 1:40
// cone every 5 mm is the cone, to round-off.
TEST(ProfileCurve, AMeasuredConeIsTheCone) {
  std::ostringstream csv;
  for (int i = -10; i <= 10; ++i) csv << i * 0.005 << ',' << 0.475 - 0.025 * i * 0.005 << '\n';
  JointParams joint;
  joint.crown_radius_m = 0.3;
  WheelParams cone;
  cone.width_m = 0.04;
  cone.lateral_m = 0.002;
  cone.conicity = 0.025;
  WheelParams measured = cone;
  measured.conicity = 0.0;
  measured.measured_tread = std::make_shared<const ProfileCurve>(read_profile_csv(csv.str(), "cone.csv", ProfileKind::wheel_tread));
  const double a = predict_impact(joint, cone).impulse.exact_Ns;
  const double b = predict_impact(joint, measured).impulse.exact_Ns;
  EXPECT_NEAR(b, a, 1e-10 * a);
}

// A measured tread that ends exactly where the wheel does (points over
// +-35 mm, a 70 mm wheel whose far rim stands on the head): the envelope's
// slices across the span must not step past the last point. lo + (hi - lo)
// rounded an ulp past hi and the spline through the points (tolerance 0)
// threw boost's "outside of allowed range" for 1 in 4 of these y_w; with
// the default smoothing it read the end's straight line instead. The
// support is checked against the best of 4001 slices across the span (rim
// included): a grid's maximum lies below the true one by at most
// |S''| h^2 / 8 (h = 17.4 um; |S''| about 1 / (0.3 m crown) + 2 (the
// tread's r'') = 5.3 /m: 2.0e-10 m; 1.2e-10 measured), and the envelope
// cannot lie above every slice.
TEST(ProfileCurve, ATreadEndingAtTheWheelsRimStaysInsideItsPoints) {
  std::ostringstream csv;
  csv.precision(17);
  for (int i = -35; i <= 35; ++i) {
    const double y = i * 1e-3;
    csv << y << ',' << 0.475 - 0.03 * y - y * y << '\n';  // a 1:33 cone bent by a 0.5 m crown
  }
  JointParams joint;
  joint.rail_profile = RailProfile::en_60e1;
  joint.half_width_m = 0.036;
  joint.theta_rad = 1.0;
  joint.beta_rad = 0.02;
  joint.dip_shape = DipShape::quadratic;
  joint.dip_length_m = 0.3;
  WheelParams wheel;
  wheel.width_m = 0.07;
  wheel.measured_tread = std::make_shared<const ProfileCurve>(read_profile_csv(csv.str(), "tread.csv", ProfileKind::wheel_tread, 0.0));
  wheel.radius_m = wheel.measured_tread->value_m(0.0);
  for (int n = 0; n < 40; ++n) {
    wheel.lateral_m = -0.0015 - 0.001 * n / 40.0;  // the far rim at 0.0335-0.0325 m, on the head
    ASSERT_NO_THROW(check_parameters(joint, wheel));
    const LateralSpan span = wheel_span_on_head(joint, wheel);
    for (const auto& [rail, x] : {std::pair{0, -0.1}, std::pair{0, -0.01}, std::pair{1, 0.01}, std::pair{1, 0.1}}) {
      RailSupport support;
      ASSERT_NO_THROW(support = rail_support(joint, wheel, rail, x)) << "y_w " << wheel.lateral_m;
      double best = -INFINITY;
      constexpr int kGrid = 4000;
      for (int i = 0; i <= kGrid; ++i) {
        const double y = i == kGrid ? span.hi_m : span.lo_m + (span.hi_m - span.lo_m) * i / kGrid;
        best = std::max(best, slice_rail_support(joint, wheel, rail, y, x).centre_z_m);
      }
      EXPECT_GE(support.centre_z_m, best - 1e-15) << "y_w " << wheel.lateral_m << " x " << x;
      EXPECT_LE(support.centre_z_m, best + 2.5e-10) << "y_w " << wheel.lateral_m << " x " << x;
    }
  }
}

// 60E1 measured every 0.05 mm (points from the tests' own construction of
// the drawing, general_geometry_reference.h) under a 1:40 cone: the jump
// within 1e-5 of the drawn head's. Calibrated on the sampling: every
// 0.5 mm it was 1.6e-4 off, every 0.25 mm 6.1e-5, every 0.05 mm 4e-6 (the
// spline's slope, which places the contact, converges as about h^1.7).
TEST(ProfileCurve, AMeasured60E1ConvergesOnTheDrawnOne) {
  std::ostringstream csv;
  csv.precision(17);
  const int n = 1440;
  for (int i = 0; i <= n; ++i) {
    const double y = -0.036 + 0.072 * i / n;
    csv << y << ',' << static_cast<double>(reference::head_60e1_m(y)) << '\n';
  }
  JointParams drawn;
  drawn.theta_rad = std::numbers::pi / 6.0;
  drawn.rail_profile = RailProfile::en_60e1;
  drawn.half_width_m = 0.036;
  JointParams measured = drawn;
  measured.rail_profile = RailProfile::measured;
  measured.measured_head = std::make_shared<const ProfileCurve>(read_profile_csv(csv.str(), "60e1.csv", ProfileKind::rail_head, 0.0));
  WheelParams wheel;
  wheel.width_m = 0.07;
  wheel.lateral_m = 0.0;
  wheel.conicity = 0.025;
  const double a = predict_impact(drawn, wheel).impulse.exact_Ns;
  const double b = predict_impact(measured, wheel).impulse.exact_Ns;
  EXPECT_NEAR(b, a, 1e-5 * a);
}

}  // namespace
}  // namespace railjoint
