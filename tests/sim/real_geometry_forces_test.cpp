// Force runs on real wheels and rails (sim/force_contact_geometry.h): the
// static state against Hertz's elliptical law at the tangency found by hand,
// and the stiff plastic limit against the analytic jump of that geometry.

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "models/hertz_ellipse.h"
#include "sim/crossing_model.h"
#include "sim/setting_checks.h"
#include "sim/simulate_crossing.h"

namespace railjoint {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kWheelRadius_m = 0.475;
constexpr double kHalfDip = 0.015;  // beta / 2 of the default joint

SimSettings hertz_settings() {
  SimSettings s;
  s.make_inertial().contact.emplace<ElasticCrossingSettings>();
  return s;
}

struct RealGeometry {
  const char* name;
  bool sixty_e1;          // else an arc of crown_radius
  double crown_radius_m;  // the arc's, or 60E1's 300 mm top arc
  double conicity;
};

JointParams joint_of(const RealGeometry& g) {
  JointParams joint;
  joint.theta_rad = kPi / 2.0;
  joint.half_width_m = 0.036;
  if (g.sixty_e1) {
    joint.rail_profile = RailProfile::en_60e1;
  } else {
    joint.crown_radius_m = g.crown_radius_m;
  }
  return joint;
}

WheelParams wheel_of(const RealGeometry& g, double speed_m_per_s) {
  WheelParams wheel;
  wheel.width_m = 0.07;
  wheel.lateral_m = 0.0;  // the plane on the crest: the tread spans the tangency
  wheel.conicity = g.conicity;
  wheel.speed_m_per_s = speed_m_per_s;
  return wheel;
}

SimulationResult run(const RealGeometry& g, const SimSettings& settings, double speed_m_per_s = 30.0) {
  JointParams joint = joint_of(g);
  const WheelParams wheel = wheel_of(g, speed_m_per_s);
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, settings));
  return simulate_crossing(joint, wheel, settings);
}

// By hand: in the slice at y the incoming rail's top is the line
// z = c(y) - t x (t = tan(beta/2)), and the cone's slice of radius
// r(y) = R - kappa y (the wheel's plane at y = 0) touches it with its centre at c(y) - t X + r(y) sqrt(1 + t^2).
// The wheel rests on the slice where that is highest:
// c'(y) = kappa sqrt(1 + t^2) =: s, on the arc c = sqrt(rho^2 - y^2) - rho at
// y = -s rho / sqrt(1 + s^2). There the rail's normal is (t, -s, 1) / |.|,
// n_z = 1 / sqrt(1 + t^2 + s^2), and the principal curvatures are the
// rolling circle's cos(psi) / r (psi = atan(kappa), Meusnier), 0 for the
// cone across, 1 / rho for the arc, 0 along the straight rail. With
// P0 = W the static load, the normal force is W / n_z and the approach
// G (W / n_z)^(2/3), G Hertz's elliptical constant of those curvatures.
struct StaticByHand {
  double contact_y_m, n_z, G;
};

StaticByHand static_by_hand(const RealGeometry& g) {
  const double t = std::tan(kHalfDip);
  const double s = g.conicity * std::sqrt(1.0 + t * t);
  StaticByHand out;
  out.contact_y_m = -s * g.crown_radius_m / std::sqrt(1.0 + s * s);
  out.n_z = 1.0 / std::sqrt(1.0 + t * t + s * s);
  const double r = kWheelRadius_m - g.conicity * out.contact_y_m;
  ContactCurvatures k;
  k.wheel_along_x_per_m = 1.0 / (r * std::sqrt(1.0 + g.conicity * g.conicity));
  k.rail_across_y_per_m = 1.0 / g.crown_radius_m;
  out.G = elliptical_hertz(relative_curvatures(k), HertzMaterial{})->hertz_constant_m_per_N2_3;
  return out;
}

class StaticState : public ::testing::TestWithParam<RealGeometry> {};

TEST_P(StaticState, ApproachIsTheEllipticalHertzLawAtTheTangency) {
  const RealGeometry& g = GetParam();
  const StaticByHand hand = static_by_hand(g);
  const SimulationResult r = run(g, hertz_settings());
  ASSERT_TRUE(r.inertial() && r.inertial()->forces);
  const ForceOutcome& f = *r.inertial()->forces;
  const double W = 112.5e3 + 750.0 * 9.81;
  const double approach_m = hand.G * std::cbrt((W / hand.n_z) * (W / hand.n_z));
  EXPECT_NEAR(f.hertz_constant_m_per_N2_3, hand.G, 1e-9 * hand.G);
  EXPECT_EQ(f.hertz_patches.at_p0.law, "elliptical");
  EXPECT_NEAR(f.hertz_patches.at_p0.contact_y_m, hand.contact_y_m, 1e-9);
  double worst = 0.0, worst_y = 0.0;
  int checked = 0;
  for (const WheelSample& s : r.trajectory.samples) {
    if (s.centre_m.x() > r.prediction().impact_wheel_x_m - 0.02) break;
    for (const ContactSample& c : s.contacts) {
      if (c.rail_index != 0) continue;
      worst = std::max(worst, std::abs(-c.distance_m / approach_m - 1.0));
      worst_y = std::max(worst_y, std::abs(c.point_on_rail_m.y() - hand.contact_y_m));
      ++checked;
    }
  }
  std::printf("%s: G %.6e (hand %.6e), contact y %.6f mm, approach %.4e m, worst relative error %.2e over %d steps\n",
              g.name, f.hertz_constant_m_per_N2_3, hand.G, hand.contact_y_m * 1e3, approach_m, worst, checked);
  EXPECT_GT(checked, 100);
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(worst_y, 1e-9);
  // The patch at P0 by Hertz: p0 = 3 N / (2 pi a b).
  ASSERT_TRUE(f.hertz_patches.at_p0.patch);
  const HertzPatch& p = *f.hertz_patches.at_p0.patch;
  EXPECT_NEAR(p.max_pressure_Pa, 3.0 * (W / hand.n_z) / (2.0 * kPi * p.semi_axis_x_m * p.semi_axis_y_m),
              1e-6 * p.max_pressure_Pa);
}

INSTANTIATE_TEST_SUITE_P(CrownAndSixtyE1UnderACone, StaticState,
                         ::testing::Values(RealGeometry{"crown 300 mm + 1:40", false, 0.3, 0.025},
                                           RealGeometry{"crown 500 mm + 1:20", false, 0.5, 0.05},
                                           RealGeometry{"60E1 + 1:40", true, 0.3, 0.025}),
                         [](const auto& param_info) { return std::string(param_info.param.sixty_e1 ? "SixtyE1" : "Crown") +
                                                       std::to_string(param_info.index); });

// The rigid limit: a plastic (e = 0) contact made ever stiffer carries the
// kinematic jump of that geometry (models/, railjoint analytic), as on the
// flat head (elastic_crossing_test.cpp); the 1e-3.
TEST(RealGeometryForces, AStiffPlasticContactCarriesTheAnalyticJump) {
  for (const RealGeometry& g : {RealGeometry{"crown 300 mm + 1:40", false, 0.3, 0.025},
                                RealGeometry{"60E1 + 1:40", true, 0.3, 0.025}}) {
    double ratio = 0.0;
    for (const auto& [stiffening, step_s] : {std::pair{1.0, 2e-7}, std::pair{0.01, 1e-8}}) {
      SimSettings settings = hertz_settings();
      settings.elastic()->contact.hertz_constant_m_per_N2_3 = static_by_hand(g).G * stiffening;
      settings.elastic()->contact.restitution = 0.0;
      settings.make_inertial().force_time_step_s = step_s;
      settings.approach_distance_m = 0.005;
      settings.run_out_time_s = 0.001;
      const SimulationResult r = run(g, settings);
      ASSERT_TRUE(r.impact_found());
      ratio = r.impulse_Ns() / r.prediction().impulse.exact_Ns;
      std::printf("%s, G x %g, step %g s: pulse %.4f N s = %.6f x the analytic jump %.4f N s; %s\n", g.name, stiffening,
                  step_s, r.impulse_Ns(), ratio, r.prediction().impulse.exact_Ns,
                  r.verdict.ok ? "ok" : r.verdict.reason.c_str());
    }
    EXPECT_NEAR(ratio, 1.0, 1e-3) << g.name;
  }
}

}  // namespace
}  // namespace railjoint
