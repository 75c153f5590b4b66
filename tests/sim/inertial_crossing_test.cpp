// The inertial mode: a wheel pressed on only by its weight and the static
// wheel load, free to leave the rail. Each test derives its expected value by
// hand (comments) or from an independent model, never from the simulation.
//
// Thesis parameters unless a test says otherwise: R = 0.475 m, M = 750 kg,
// beta = 0.03 rad, b_t = 20 mm, thin disc simulated as a 1 mm wide cylinder,
// static wheel load F = 112.5 kN (thesis table 6.1), so the static contact
// force is W = F + M g = 112500 + 750 * 9.81 = 119857.5 N and a flying
// wheel falls at g_eff = W / M = 159.81 m/s^2. The joint is made 3 m long so
// that flights of up to ~17 ms at 50 m/s land on the outgoing rail.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "models/impact_prediction.h"
#include "models/liftoff.h"
#include "sim/crossing_cases.h"
#include "sim/impact_force_estimate.h"
#include "sim/simulate_crossing.h"

namespace railjoint {
namespace {

constexpr double kGravity = 9.81;

CrossingCase long_joint(CrossingCase c) {
  c.joint.length_m = 3.0;
  return c;
}

SimSettings inertial(double run_out_time_s = 0.02) {
  SimSettings s;
  s.make_inertial();
  s.run_out_time_s = run_out_time_s;
  return s;
}

double static_load_N(const SimSettings& s, const WheelParams& wheel) {
  return s.inertial()->wheel_load_N + wheel.mass_kg * kGravity;
}

// Angle of the radius to the corner the kinematic wheel pivots about at the
// joint, for the wheel as simulated (1 mm cylinder): sin(phi) = x_A / R with
// x_A the lead of A over the centre line at the two-point contact.
double pivot_angle_rad(const CrossingCase& c) {
  // The simulated stand-in of a thin disc strikes as the disc does (its inner
  // face lies in the disc's plane, sim/setting_checks.h): the scene's wheel.
  const ImpactPrediction p = predict_impact(c.joint, c.wheel);
  return std::asin(std::abs(p.impact_wheel_x_m - p.contact_A_m.x()) / c.wheel.radius_m);
}

// Centre height of a sample-interpolated trajectory at time t.
double centre_z_at(const Trajectory& t, double time_s) {
  const auto& s = t.samples;
  auto it = std::lower_bound(s.begin(), s.end(), time_s, [](const WheelSample& w, double x) { return w.time_s < x; });
  if (it == s.begin()) return s.front().centre_m.z();
  if (it == s.end()) return s.back().centre_m.z();
  const WheelSample& b = *it;
  const WheelSample& a = *(it - 1);
  const double f = (time_s - a.time_s) / (b.time_s - a.time_s);
  return a.centre_m.z() + f * (b.centre_m.z() - a.centre_m.z());
}

// ---------------------------------------------------------------------------
// Glued wheel: the first jump of both modes agrees.

struct GluedCase {
  std::string name;
  CrossingCase crossing;
  /// Load as a multiple of the one that just keeps the wheel on the pivot at
  /// the joint (0: the default 112.5 kN).
  double load_factor;
  bool glued_throughout;
};

// Test names in ctest's list: the case name, not the struct's bytes.
void PrintTo(const GluedCase& c, std::ostream* out) { *out << c.name; }

class GluedWheel : public testing::TestWithParam<GluedCase> {};

TEST_P(GluedWheel, FirstJumpMatchesTheKinematicMode) {
  const GluedCase& g = GetParam();
  const CrossingCase c = long_joint(g.crossing);
  SimSettings in = inertial(0.004);
  if (g.load_factor > 0.0) {
    // W = factor * M v^2 / (R cos^3 phi): the pivot about the corner is
    // followed with margin (models/liftoff.h).
    const double W = g.load_factor * pivot_following_load_N(c.wheel.mass_kg, c.wheel.radius_m, c.wheel.speed_m_per_s,
                                                            pivot_angle_rad(c));
    in.make_inertial().wheel_load_N = W - c.wheel.mass_kg * kGravity;
  }
  const SimulationResult kinematic = simulate_crossing(c.joint, c.wheel, SimSettings{});
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, in);
  ASSERT_NE(r.inertial(), nullptr);
  const double difference = (r.impulse_Ns() - kinematic.impulse_Ns()) / kinematic.impulse_Ns();
  std::cout << g.name << ": inertial jump " << r.impulse_Ns() << " N s, kinematic mode " << kinematic.impulse_Ns()
            << " N s, exact " << r.prediction().impulse.exact_Ns << " N s, difference " << 100 * difference
            << " %, flights " << r.inertial()->flights.size() << ", max deviation " << r.inertial()->max_deviation_m
            << " m\n";
  ASSERT_TRUE(r.impact_found());
  // Both runs see the same geometry and contact model up to the jump; only
  // the load differs (100 kN preload or the load above). Measured: 0
  // (scenario 1), 8.9e-6 (scenario 2), 1.1e-6 (step down): 1e-4.
  EXPECT_NEAR(difference, 0.0, 1e-4);
  EXPECT_NEAR(r.impact->wheel_x_m(), kinematic.impact->wheel_x_m(), 1e-4);
  if (g.glued_throughout) {
    EXPECT_TRUE(r.inertial()->flights.empty());
    EXPECT_TRUE(r.inertial()->followed_kinematic_path);
    // One impact, so the total is the jump.
    EXPECT_EQ(r.trajectory.impacts.size(), 1u);
    EXPECT_NEAR(r.inertial()->total_impulse_Ns, r.impulse_Ns(), 1e-9);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, GluedWheel,
    testing::Values(GluedCase{"scenario1_theta45", inclined_crossing("s1", 45.0, 0.002), 0.0, true},
                    // The strike at A happens before any pivot: the default
                    // load does not keep the wheel on the corner after it (it
                    // flies, see below), but the jump itself is unaffected.
                    GluedCase{"scenario2_theta30", inclined_crossing("s2", 30.0, 0.015), 0.0, false},
                    // The step down jumps on landing: the wheel must follow the
                    // pivot about the corner it rolls off, twice the load that
                    // just holds it there.
                    GluedCase{"step_down_theta30", inclined_crossing("down", 30.0, -0.015), 2.0, true}),
    [](const testing::TestParamInfo<GluedCase>& param_info) { return param_info.param.name; });

TEST(InertialCrossing, StepDownUnderTheServiceLoadLeavesTheCornerAndLandsSofter) {
  // At 50 m/s the 112.5 kN load cannot hold the wheel on the corner it rolls
  // off: v_c(beta/2) = sqrt(W R cos^3(0.015) / M) = 8.711 m/s. It flies and
  // lands on the outgoing rail with the vertical velocity it gathered under
  // g_eff instead of the pivot's -v tan(alpha): the landing jump is smaller
  // than the kinematic one (2113 N s).
  const CrossingCase c = long_joint(inclined_crossing("down", 30.0, -0.015));
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, inertial(0.004));
  std::cout << "step down: jump " << r.impulse_Ns() << " N s (kinematic " << r.prediction().impulse.exact_Ns
            << " N s), flights " << r.inertial()->flights.size() << ", predicted lift-off above "
            << r.inertial()->pivot_liftoff_speed_m_per_s << " m/s\n";
  ASSERT_TRUE(r.impact_found());
  EXPECT_TRUE(r.inertial()->liftoff_predicted);
  ASSERT_EQ(r.inertial()->flights.size(), 1u);
  EXPECT_TRUE(r.trajectory.impacts[static_cast<std::size_t>(r.inertial()->joint_impact_index)].landing);
  EXPECT_LT(r.impulse_Ns(), 0.8 * r.prediction().impulse.exact_Ns);
  EXPECT_FALSE(r.inertial()->followed_kinematic_path);
}

// ---------------------------------------------------------------------------
// Lift-off against the model's critical speed.

struct LiftoffCase {
  std::string name;
  CrossingCase crossing;
  double flat_approach_m;
  double critical_speed_m_per_s;  ///< the load is chosen so the model puts v_c here (0: keep 112.5 kN)
  double speed_factor;            ///< v / v_c
  bool expect_liftoff;
};

// Test names in ctest's list: the case name, not the struct's bytes.
void PrintTo(const LiftoffCase& c, std::ostream* out) { *out << c.name; }

class LiftoffThreshold : public testing::TestWithParam<LiftoffCase> {};

TEST_P(LiftoffThreshold, SimulationAgreesWithThePivotModel) {
  const LiftoffCase& l = GetParam();
  CrossingCase c = long_joint(l.crossing);
  SimSettings s = inertial(0.005);
  s.make_inertial().flat_approach_m = l.flat_approach_m;
  const double M = c.wheel.mass_kg, R = c.wheel.radius_m;
  // The corner: A at the joint, or the entry kink (radius beta/2 from the
  // vertical where the arc ends, models/liftoff.h).
  const double phi = l.flat_approach_m > 0.0 ? c.joint.beta_rad / 2.0 : pivot_angle_rad(c);
  double v_c = 0.0;
  if (l.critical_speed_m_per_s > 0.0) {
    s.make_inertial().wheel_load_N = pivot_following_load_N(M, R, l.critical_speed_m_per_s, phi) - M * kGravity;
    v_c = l.critical_speed_m_per_s;
  } else {
    v_c = pivot_liftoff_speed_m_per_s(M, R, static_load_N(s, c.wheel), phi);
  }
  c.wheel.speed_m_per_s = l.speed_factor * v_c;
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, s);
  const InertialOutcome& o = *r.inertial();
  std::cout << l.name << ": v_c " << v_c << " m/s, v " << c.wheel.speed_m_per_s << " m/s, load "
            << s.inertial()->wheel_load_N << " N, flights " << o.flights.size()
            << ", largest rise above the kinematic path " << o.max_rise_m * 1e6 << " um\n";
  EXPECT_EQ(!o.flights.empty(), l.expect_liftoff);
  EXPECT_EQ(o.liftoff_predicted, l.expect_liftoff);
}

// Scenario-2 pivot and step-down pivot: the load puts v_c at 30 m/s;
// measured simulated thresholds (bisection on v) 30.39 and 29.95 m/s, so +-3 %
// separates them with margin. Entry kink of a flat approach under the
// service load (v_c = 8.711 m/s): near v_c the wheel leaves the arc by only
// (v^2/R - g_eff) t^2 / 2, a few um over the 0.8 ms arc, the size of the
// rigid contact's 1 um chatter band; the detected threshold scattered
// between 8.8 and 9.15 m/s (+1 .. +5 %): +-10 %.
INSTANTIATE_TEST_SUITE_P(
    Cases, LiftoffThreshold,
    testing::Values(
        LiftoffCase{"scenario2_below", inclined_crossing("s2", 30.0, 0.015), 0.0, 30.0, 0.97, false},
        LiftoffCase{"scenario2_above", inclined_crossing("s2", 30.0, 0.015), 0.0, 30.0, 1.03, true},
        LiftoffCase{"step_down_below", inclined_crossing("down", 30.0, -0.015), 0.0, 30.0, 0.97, false},
        LiftoffCase{"step_down_above", inclined_crossing("down", 30.0, -0.015), 0.0, 30.0, 1.03, true},
        LiftoffCase{"entry_kink_below", inclined_crossing("s1", 30.0, 0.002), 0.5, 0.0, 0.90, false},
        LiftoffCase{"entry_kink_above", inclined_crossing("s1", 30.0, 0.002), 0.5, 0.0, 1.10, true}),
    [](const testing::TestParamInfo<LiftoffCase>& param_info) { return param_info.param.name; });

// ---------------------------------------------------------------------------
// The flight after a scenario-2 strike.

TEST(InertialCrossing, FlightAfterTheStrikeIsBallistic) {
  // After the strike at A (scenario 2, theta 30 deg, y_w 15 mm, 50 m/s) the
  // wheel leaves with w0 = zdot+ (taken from the simulation: this tests the
  // flight, not the jump) and falls at g_eff = W / M. It lands when the
  // centre is back on the line it follows on the outgoing rail,
  //   z_out(x) = tan(beta/2) x + R / cos(beta/2),
  // which lies gap = z_out(x_imp) - z_imp above the centre at the strike and
  // rises at tan(beta/2) v. models/liftoff.h ballistic_flight solves
  //   w0 t - g t^2 / 2 = gap + tan(beta/2) v t;
  // the apex is w0^2 / (2 g) above the strike.
  const CrossingCase c = long_joint(inclined_crossing("s2", 30.0, 0.015));
  SimSettings s = inertial(0.02);
  // Bullet's semi-implicit Euler lags a ballistic height by g dt t / 2: at
  // the default 1e-4 s that is 0.8 % of the apex; at 1e-5 s, 0.08 %.
  s.time_step_s = 1e-5;
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, s);
  const InertialOutcome& o = *r.inertial();
  ASSERT_TRUE(r.impact_found());
  ASSERT_GE(r.trajectory.impacts.size(), 2u);
  ASSERT_EQ(o.flights.size(), 1u);
  const ImpactEvent& landing = r.trajectory.impacts[static_cast<std::size_t>(o.joint_impact_index) + 1];
  EXPECT_TRUE(landing.landing);

  const double t_half = std::tan(c.joint.beta_rad / 2.0);
  const double g = static_load_N(s, c.wheel) / c.wheel.mass_kg;
  const double v = c.wheel.speed_m_per_s;
  const double z_imp = centre_z_at(r.trajectory, r.impact->time_s());
  const double gap = t_half * r.impact->wheel_x_m() + c.wheel.radius_m / std::cos(c.joint.beta_rad / 2.0) - z_imp;
  const BallisticFlight expected = ballistic_flight(r.impact->zdot_after_m_per_s(), g, v, gap, t_half);

  const double flight_time = landing.time_s - r.impact->time_s();
  double apex = 0.0;
  for (const WheelSample& w : r.trajectory.samples) {
    if (w.time_s > r.impact->time_s() && w.time_s < landing.time_s) apex = std::max(apex, w.centre_m.z() - z_imp);
  }
  std::cout << "w0 " << r.impact->zdot_after_m_per_s() << " m/s, gap " << gap * 1e3 << " mm; flight "
            << flight_time * 1e3 << " ms (ballistic " << expected.flight_time_s * 1e3 << " ms), apex " << apex * 1e3
            << " mm (ballistic " << expected.apex_height_m * 1e3 << " mm), landing jump " << landing.momentum_jump_Ns
            << " N s\n";
  // Measured: flight time 0.06 %, apex 0.07 % short (the integrator's lag
  // above). Tolerances: 0.5 % and 1 %.
  EXPECT_NEAR(flight_time / expected.flight_time_s, 1.0, 5e-3);
  EXPECT_NEAR(apex / expected.apex_height_m, 1.0, 1e-2);
  // The landing jump: from w0 - g t to the outgoing rail's +v tan(beta/2),
  // M (v tan(beta/2) - landing zdot). Measured 0.13 % short (the flight
  // time's error times g); 1 %.
  const double expected_landing_jump = c.wheel.mass_kg * (v * t_half - expected.landing_zdot_m_per_s);
  EXPECT_NEAR(landing.momentum_jump_Ns / expected_landing_jump, 1.0, 1e-2);
  // Every jump is counted once in the total.
  EXPECT_NEAR(o.total_impulse_Ns, r.impulse_Ns() + landing.momentum_jump_Ns, 1e-6);
}

// ---------------------------------------------------------------------------
// Horizontal momentum.

TEST(InertialCrossing, HeldSpeedCarrierAbsorbsTheStrikesHorizontalImpulse) {
  // Frictionless, the strike at A pushes along A's normal (-sin a, cos a):
  // its x part is -Delta p_z tan(a), taken by the carrier (speed held).
  const CrossingCase c = long_joint(inclined_crossing("s2", 30.0, 0.015));
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, inertial(0.004));
  ASSERT_TRUE(r.impact_found());
  const double a = pivot_angle_rad(c);
  const double expected = -r.impulse_Ns() * std::tan(a);
  std::cout << "horizontal impulse " << r.inertial()->joint_horizontal_impulse_Ns << " N s, -dp tan(alpha) " << expected
            << " N s, xdot " << r.impact->xdot_before_m_per_s() << " -> " << r.impact->xdot_after_m_per_s() << "\n";
  // Measured 0.22 % (the contact sum is 0.1 % off the jump, the cut-edge
  // normal's tilt enters through tan(alpha)); 1 % still tells the 5 % of a
  // closest-point normal (sim/DESIGN.md "What was measured with Bullet").
  EXPECT_NEAR(r.inertial()->joint_horizontal_impulse_Ns / expected, 1.0, 1e-2);
  EXPECT_DOUBLE_EQ(r.impact->xdot_after_m_per_s(), c.wheel.speed_m_per_s);
}

TEST(InertialCrossing, FreeCarrierLosesTheMomentumOfTheHorizontalImpulse) {
  // Free horizontal motion, wheel + carrier M_h = 750 + 250 = 1000 kg
  // horizontally, M = 750 kg vertically. A plastic frictionless strike at A
  // (normal n = (-sin a, cos a)) gives the impulse J n with J such that the
  // normal velocity vanishes after it:
  //   v_n = -v sin a + zdot cos a,  zdot = -v tan(beta/2),
  //   J (sin^2 a / M_h + cos^2 a / M) = -v_n,
  //   Delta xdot = -J sin a / M_h,  Delta p_z = J cos a.
  // (M_h -> infinity gives back M v (tan a + tan(beta/2)).)
  const CrossingCase c = long_joint(inclined_crossing("s2", 30.0, 0.015));
  SimSettings s = inertial(0.004);
  s.make_inertial().horizontal = HorizontalMotion::free;
  s.make_inertial().carrier_mass_kg = 250.0;
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, s);
  const InertialOutcome& o = *r.inertial();
  ASSERT_TRUE(r.impact_found());
  const double M = c.wheel.mass_kg, M_h = M + 250.0;
  const double a = pivot_angle_rad(c);
  const double v = r.impact->xdot_before_m_per_s();
  const double zdot = r.impact->zdot_before_m_per_s();
  const double v_n = -v * std::sin(a) + zdot * std::cos(a);
  const double J = -v_n / (std::sin(a) * std::sin(a) / M_h + std::cos(a) * std::cos(a) / M);
  const double expected_dxdot = -J * std::sin(a) / M_h;
  const double expected_dpz = J * std::cos(a);
  const double dxdot = r.impact->xdot_after_m_per_s() - r.impact->xdot_before_m_per_s();
  std::cout << "free carrier: xdot " << r.impact->xdot_before_m_per_s() << " -> " << r.impact->xdot_after_m_per_s()
            << " (dxdot " << dxdot << ", hand " << expected_dxdot << ", impulse / M_h "
            << o.joint_horizontal_impulse_Ns / M_h << "), dp_z " << r.impulse_Ns() << " (hand " << expected_dpz
            << ") N s\n";
  // The carrier's loss is the contact's x impulse over wheel + carrier
  // (Bullet's linear-factor trick, crossing_world.cpp): measured 0.08 %: 1 %.
  EXPECT_NEAR(dxdot / (o.joint_horizontal_impulse_Ns / M_h), 1.0, 1e-2);
  // And what the plastic-impact hand formula predicts: measured 0.2 % (the
  // cut-edge normal's tilt enters through sin a ~ 0.04): 2 %. The vertical
  // jump: measured 0.04 %, 0.3 % (below the 0.5 % accuracy target).
  EXPECT_NEAR(dxdot / expected_dxdot, 1.0, 2e-2);
  EXPECT_NEAR(r.impulse_Ns() / expected_dpz, 1.0, 3e-3);
  EXPECT_LT(dxdot, 0.0);
}

// ---------------------------------------------------------------------------
// Friction, restitution.

TEST(InertialCrossing, FrictionRollsTheWheelWithoutSlip) {
  // With friction the wheel spins about its axle (solid disc, I = M R^2 / 2).
  // Rolling on the incoming slope its contact point stays at rest: the centre
  // moves at v / cos(beta/2) along the slope, on the wheel's contact radius
  // r = R + slop (the exact narrow phase puts the contact point on it; slop 0
  // by default), so omega = v / (r cos(beta/2)) = 50 / (0.475 * 0.99988750) = 105.2750 rad/s.
  const CrossingCase c = long_joint(inclined_crossing("s2", 30.0, 0.015));
  SimSettings s = inertial(0.004);
  s.friction = 0.3;
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, s);
  ASSERT_TRUE(r.impact_found());
  const double r_roll = c.wheel.radius_m + s.slop_m;
  const double expected = c.wheel.speed_m_per_s / (r_roll * std::cos(c.joint.beta_rad / 2.0));
  double worst = 0.0;
  for (const WheelSample& w : r.trajectory.samples) {
    if (w.time_s <= 0.0 || w.time_s > 0.5 * r.impact->time_s()) continue;
    worst = std::max(worst, std::abs(w.spin_rate_rad_per_s / expected - 1.0));
  }
  std::cout << "spin before the joint within " << worst << " of v / (r cos(beta/2)); jump " << r.impulse_Ns()
            << " N s (frictionless exact " << r.prediction().impulse.exact_Ns << ")\n";
  // Rolling on a plane needs no friction force once started on the rolling
  // radius: the solver's round-off only (measured 3.7e-14). 1e-12. (Started
  // on the cylinder's core radius, R - margin, it slipped by up to 1.8e-7
  // while friction caught up over the first microsecond steps.)
  EXPECT_LT(worst, 1e-12);
  ASSERT_TRUE(r.impact_found());
}

TEST(InertialCrossing, RestitutionAddsItsShareOfTheNormalImpulse) {
  // Scenario 1: the plastic impulse on the outgoing rail removes the normal
  // approach velocity; a restitution e returns e times it, so the vertical
  // jump is (1 + e) times the plastic one and the wheel bounces (flies).
  const CrossingCase c = long_joint(inclined_crossing("s1", 45.0, 0.002));
  SimSettings s = inertial(0.004);
  s.restitution = 0.5;
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, s);
  const double ratio = r.impulse_Ns() / r.prediction().impulse.exact_Ns;
  std::cout << "restitution 0.5: jump ratio " << ratio << ", flights " << r.inertial()->flights.size() << "\n";
  // Measured 1.50005; 0.5 % (the accuracy target).
  EXPECT_NEAR(ratio, 1.5, 7.5e-3);
  EXPECT_FALSE(r.inertial()->flights.empty());
}

// ---------------------------------------------------------------------------
// Compliant contact: finite force.

// Independent reference: the wheel centre (a circle of radius R, horizontal
// speed v held) over the two rail tops of the governing slice as straight
// segments, each pushing with k * overlap along the line from its nearest
// point to the centre; semi-implicit Euler with dt = 1e-8 s (omega dt =
// 1.4e-5). Returns the largest summed vertical force [N].
double two_rail_spring_peak_N(const CrossingCase& c, double slice_y_m, double k, double W) {
  const double t = std::tan(c.joint.beta_rad / 2.0);
  const double L = c.joint.length_m, R = c.wheel.radius_m, M = c.wheel.mass_kg, v = c.wheel.speed_m_per_s;
  const double xc = slice_y_m / std::tan(c.joint.theta_rad);
  const double seg[2][4] = {{-L / 2, t * L / 2, xc, -t * xc}, {xc, t * xc, L / 2, t * L / 2}};
  const double cos2 = 1.0 / (1.0 + t * t);
  double x = -0.02, z = R / std::cos(c.joint.beta_rad / 2.0) - t * x - W / (k * cos2), zdot = -v * t;
  double peak = 0.0;
  const double dt = 1e-8;
  // Past the peak: two quarter periods of the contact spring (1.1 ms each) and 20 mm.
  const double x_end = 0.02 + v * 3e-3;
  while (x < x_end) {
    double force = 0.0;
    for (const auto& s : seg) {
      const double dx = s[2] - s[0], dz = s[3] - s[1];
      const double u = std::clamp(((x - s[0]) * dx + (z - s[1]) * dz) / (dx * dx + dz * dz), 0.0, 1.0);
      const double px = x - (s[0] + u * dx), pz = z - (s[1] + u * dz);
      const double d = std::hypot(px, pz);
      if (d < R) force += k * (R - d) * pz / d;
    }
    peak = std::max(peak, force);
    zdot += (force - W) / M * dt;
    z += zdot * dt;
    x += v * dt;
  }
  return peak;
}

struct CompliantPeak {
  double simulated_N;
  double spring_model_N;
  double p1_N;
  double p1_from_jump_N;  ///< P1 fed with the kinematic jump Delta p / M instead of beta v
  bool flew;
};

// By default scenario 1 (theta 45 deg, y_w 2 mm), with the linearised Hertz
// stiffness at the static load (impact_force_estimate.h: 0.475 m wheel on a
// 0.3 m rail crown, E = 210 GPa, nu = 0.3, W = 119857.5 N: k = 1.53e9 N/m).
CompliantPeak compliant_peak(double speed_m_per_s, double theta_deg = 45.0, double lateral_m = 0.002) {
  const CrossingCase c = long_joint(inclined_crossing("compliant", theta_deg, lateral_m, speed_m_per_s));
  SimSettings s = inertial(0.004);
  const double W = static_load_N(s, c.wheel);
  const double k = linearised_hertz_stiffness_N_per_m(HertzContact{}, W);
  s.make_inertial().contact.emplace<LinearContactSettings>().stiffness_N_per_m = k;
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, s);
  const InertialOutcome& o = *r.inertial();
  EXPECT_TRUE(o.compliant);
  // The 1 mm cylinder's inner face governs: slice y_w - 0.5 mm.
  const double reference = two_rail_spring_peak_N(c, c.wheel.lateral_m - SimSettings{}.disc_half_width_m, k, W);
  // Jenkins et al. (1974) P1 for a rigid track, 2 alpha = beta, unsprung mass M:
  // P0 + beta v sqrt(k M).
  const double p1 = jenkins_p1_force_N(W, c.joint.beta_rad, c.wheel.speed_m_per_s, k, c.wheel.mass_kg,
                                       std::numeric_limits<double>::infinity());
  std::cout << "v " << speed_m_per_s << " m/s, k " << k << " N/m: peak " << o.peak_force_N << " N at x "
            << o.peak_force_x_m * 1e3 << " mm; two-rail spring model " << reference << " N; P1 rigid track " << p1
            << " N (" << 100 * (o.peak_force_N / p1 - 1) << " %)\n";
  return {o.peak_force_N, reference, p1, o.compliant->rigid_track_p1_N, !o.flights.empty()};
}

TEST(InertialCrossing, CompliantPeakForceMatchesTheTwoRailSpringModelAndP1) {
  const CompliantPeak fast = compliant_peak(50.0);
  // Measured 0.2 % below the spring model: 2 %.
  EXPECT_NEAR(fast.simulated_N / fast.spring_model_N, 1.0, 2e-2);
  // P1 idealises the joint as one spring whose path kinks; here the load
  // passes from one rail end to the other while both springs carry it, which
  // the spring model above reproduces: measured 2.9 % below P1. 6 %.
  EXPECT_NEAR(fast.simulated_N / fast.p1_N, 1.0, 6e-2);
  EXPECT_LT(fast.simulated_N, fast.p1_N);
  // The undamped spring returns the energy: the wheel bounces off (e ~ 1).
  EXPECT_TRUE(fast.flew);
}

TEST(InertialCrossing, CompliantPeakAtLowSpeedStillMatchesTheSpringModelNotP1) {
  // At 10 m/s the wheel travels 11 mm in the spring's quarter period, the
  // two rail ends share the load for longer and the peak falls 20 % short of
  // P1 (measured -20.6 %), while the two-rail spring model still agrees
  // (measured 0.03 %): the difference is the joint's, not the simulation's.
  const CompliantPeak slow = compliant_peak(10.0);
  EXPECT_NEAR(slow.simulated_N / slow.spring_model_N, 1.0, 2e-2);
  EXPECT_LT(slow.simulated_N, 0.9 * slow.p1_N);
}

TEST(InertialCrossing, CompliantPeakAtAnEdgeStrikeFollowsTheNetVelocityChange) {
  // Scenario 2 (figure 4.5 point, theta 30 deg, y_w 15 mm, 50 m/s): the rigid
  // wheel strikes the cut edge with a jump Delta p / M = 2.82 m/s, almost twice
  // beta v = 1.5 m/s, then pivots about the edge for (x_A - x_w + R sin(beta/2))
  // / v = 0.54 ms before it rolls onto the far top; the spring's rise time is
  // (pi/2) sqrt(M / k) = 1.10 ms. The pivot is over before the force peaks, so
  // the spring feels the net change beta v: the peak sits near P1(beta v)
  // (measured -0.2 %) and far below P1(Delta p / M) (measured -45 %). The
  // two-rail spring model (its segments end in the corner) reproduces it.
  const CompliantPeak edge = compliant_peak(50.0, 30.0, 0.015);
  EXPECT_NEAR(edge.simulated_N / edge.spring_model_N, 1.0, 2e-2);  // as in scenario 1
  EXPECT_NEAR(edge.simulated_N / edge.p1_N, 1.0, 6e-2);
  EXPECT_LT(edge.simulated_N, 0.7 * edge.p1_from_jump_N);
}

}  // namespace
}  // namespace railjoint

namespace railjoint {
namespace {

TEST(InertialCrossing, VerdictVouchesForALandingAndSaysWhenARunEndsInFlight) {
  // The figure-4.5 point under the service load flies 17 ms after the strike
  // (models/joint_flight.h). On 3 m rails with the derived run-out the run
  // sees it land: nothing cut short, nothing sunk, the estimators agree.
  const CrossingCase c = long_joint(inclined_crossing("s2", 30.0, 0.015));
  SimSettings s;
  s.make_inertial();
  const SimulationResult landed = simulate_crossing(c.joint, c.wheel, s);
  std::cout << "derived run-out: verdict " << (landed.verdict.ok ? "ok" : "suspect: " + landed.verdict.reason)
            << ", flights " << landed.inertial()->flights.size() << "\n";
  EXPECT_TRUE(landed.verdict.ok) << landed.verdict.reason;
  ASSERT_TRUE(landed.second_impact);
  // A 4 ms run-out the user chose ends mid-flight: the jump at the joint
  // still stands, the outcome says the landing is not in the run.
  s.run_out_time_s = 0.004;
  const SimulationResult cut = simulate_crossing(c.joint, c.wheel, s);
  EXPECT_TRUE(cut.verdict.ok) << cut.verdict.reason;
  EXPECT_TRUE(cut.inertial()->ended_in_flight);
  EXPECT_FALSE(cut.second_impact);
}

}  // namespace
}  // namespace railjoint
