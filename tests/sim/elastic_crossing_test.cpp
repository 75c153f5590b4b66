// Force runs (Hertz contact, lumped track): the static state against Hertz's
// law and the springs in series by hand, and the whole contact-force history
// against an independent planar model integrated to 1e-11
// (lumped_track_reference.h).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "sim/crossing_model.h"
#include "sim/setting_checks.h"
#include "sim/simulate_crossing.h"
#include "tests/sim/force_scenes.h"

namespace railjoint {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct ForceCase {
  const char* name;
  double theta_deg;
  double lateral_m;
};

SimSettings hertz_settings(bool lumped) {
  SimSettings s;
  s.make_inertial();
  ElasticCrossingSettings& e = s.make_inertial().contact.emplace<ElasticCrossingSettings>();
  if (lumped) e.track.emplace();
  return s;
}

SimulationResult run(const ForceCase& c, const SimSettings& settings, double speed_m_per_s = 30.0) {
  JointParams joint;
  joint.theta_rad = c.theta_deg * kPi / 180.0;
  WheelParams wheel;
  wheel.lateral_m = c.lateral_m;
  wheel.speed_m_per_s = speed_m_per_s;
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, settings));
  return simulate_crossing(joint, wheel, settings);
}

// Hertz's law and the track's springs in series, by hand: on the incoming
// slope (tan(beta/2)) the contact normal leans by beta/2, so the normal
// force is N = W / cos(beta/2) and the approach G N^(2/3); the track carries
// W: rail W / k_pad + W / k_ballast below its unloaded place, sleeper W / k_ballast.
TEST(ElasticCrossing, StaticStateBeforeTheJointIsHertzAndTheSpringsInSeries) {
  const SimSettings settings = hertz_settings(true);
  const SimulationResult r = run({"square", 90.0, 0.0}, settings);
  const LumpedTrackSettings track;
  const double W = 112.5e3 + 750.0 * 9.81;
  const double G = 3.86e-8 * std::pow(0.475, -0.115);  // the commonly quoted new-wheel constant at R = 0.475 m
  const double N = W / std::cos(0.015);
  const double approach_m = G * std::cbrt(N * N);
  const double rail_z_m = -W / track.support.pad_stiffness_N_per_m - W / track.support.ballast_stiffness_N_per_m;
  const double sleeper_z_m = -W / track.support.ballast_stiffness_N_per_m;
  ASSERT_TRUE(r.inertial() && r.inertial()->forces);
  const ForceOutcome& f = *r.inertial()->forces;
  int checked = 0;
  double worst_approach = 0.0, worst_rail = 0.0, worst_sleeper = 0.0;
  for (std::size_t k = 1; k < r.trajectory.samples.size(); ++k) {
    const WheelSample& s = r.trajectory.samples[k];
    if (s.centre_m.x() > r.prediction().impact_wheel_x_m - 0.02) break;
    // On the incoming rail only: the outgoing one may be in reach (a gap below
    // the 2 mm contact breaking threshold) but is not touched.
    for (const ContactSample& contact : s.contacts) {
      if (contact.rail_index == 0) {
        worst_approach = std::max(worst_approach, std::abs(-contact.distance_m / approach_m - 1.0));
      } else {
        ASSERT_GT(contact.distance_m, 0.0) << "the outgoing rail touched at x = " << s.centre_m.x();
      }
    }
    worst_rail = std::max(worst_rail, std::abs(f.track[k].rail_z_m / rail_z_m - 1.0));
    worst_sleeper = std::max(worst_sleeper, std::abs(f.track[k].sleeper_z_m / sleeper_z_m - 1.0));
    ++checked;
  }
  std::printf("approach %.6g um over %d steps: worst relative errors approach %.3g, rail %.3g, sleeper %.3g\n",
              approach_m * 1e6, checked, worst_approach, worst_rail, worst_sleeper);
  EXPECT_GT(checked, 100);
  // The target: delta0 = G W^(2/3) to 1e-6 relative. The run starts
  // in equilibrium, so only round-off of the positions (1e-16 m on ~1 m
  // coordinates against a 1e-4 m approach: 1e-12) should remain.
  EXPECT_LT(worst_approach, 1e-6);
  EXPECT_LT(worst_rail, 1e-9);
  EXPECT_LT(worst_sleeper, 1e-9);
  EXPECT_TRUE(r.verdict.ok) << r.verdict.reason;
}

// The elastic limit. An undamped Hertz contact (restitution 1) on a rigid
// track is conservative, so the wheel leaves the outgoing rail's plane as
// fast as it met it. By hand, on a square V with slopes -+tan(beta/2): the
// wheel comes down the incoming slope at (v, -v tan(beta/2)); its velocity
// along the outgoing plane's normal n = (-sin(beta/2), cos(beta/2)) is
// -2 v sin(beta/2). Only z is free (the carrier holds x), and a vertical
// change dw moves the normal velocity by dw cos(beta/2); reversing it takes
// dw = 4 v tan(beta/2), twice the plastic (kinematic) 2 v tan(beta/2). The
// pulse's impulse above the static load, integral (F - P0) dt = M dw, falls
// short of that by what the static load carries while the contact is open or
// below P0, which vanishes with the contact's duration (~ G^(3/5) for Hertz):
// a stiffer contact must approach twice the exact jump.
TEST(ElasticCrossing, AnUndampedHertzImpactCarriesTwiceThePlasticJumpInTheStiffLimit) {
  const ForceCase square{"square", 90.0, 0.0};
  double previous_deficit = 1.0;
  for (const double stiffening : {1.0, 0.1, 0.01, 0.001}) {
    SimSettings settings = hertz_settings(false);
    settings.elastic()->contact.hertz_constant_m_per_N2_3 = 3.86e-8 * std::pow(0.475, -0.115) * stiffening;
    settings.make_inertial().force_time_step_s = 2e-7;  // >= 80 steps across the stiffest pulse (about 30 us)
    settings.run_out_time_s = 0.004;
    const SimulationResult r = run(square, settings);
    ASSERT_TRUE(r.impact_found());
    const double plastic_Ns = 2.0 * 750.0 * 30.0 * std::tan(0.015);
    const double deficit = 1.0 - r.impulse_Ns() / (2.0 * plastic_Ns);
    std::printf("G x %g: pulse impulse %.4f N s = %.6f x twice the plastic jump %.4f N s (deficit %.3g)\n", stiffening,
                r.impulse_Ns(), r.impulse_Ns() / (2.0 * plastic_Ns), plastic_Ns, deficit);
    EXPECT_GT(deficit, 0.0);  // the static load always takes a little
    // G^(3/5) per decade of G is 1 / 3.98 for one Hertz contact; measured
    // 3.8-4.4 below G / 10. From G to G / 10 the wheel spans the joint's
    // bottom on both rail ends, coupled (rail_end_patch_share.h), for a
    // good part of the pulse: measured 2.5. At least 3, and 2 there.
    EXPECT_LT(deficit, previous_deficit / (stiffening < 0.1 ? 3.0 : 2.0));
    previous_deficit = deficit;
    EXPECT_TRUE(r.verdict.ok) << r.verdict.reason;
  }
  EXPECT_LT(previous_deficit, 1e-3);  // measured 1.3e-4 at G / 1000
}

// The dissipative limits. The law's damping factor is solved so an isolated
// impact rebounds at e times its closing speed (hertz_law.h), so on the
// square V the same argument as above gives a pulse of (1 + e) times the
// plastic jump in the stiff limit: 1 for e = 0 (the kinematic jump, within
// the 1e-3), 1.5 for e = 0.5. The step shrinks with the contact so
// that about 100 steps span each pulse; the run is cut short (5 mm of
// approach, 1 ms after the joint) to keep the finest steps affordable.
TEST(ElasticCrossing, ADissipativeImpactCarriesOnePlusETimesThePlasticJumpInTheStiffLimit) {
  const ForceCase square{"square", 90.0, 0.0};
  const double plastic_Ns = 2.0 * 750.0 * 30.0 * std::tan(0.015);
  for (const double e : {0.0, 0.5}) {
    double ratio = 0.0;
    for (const auto& [stiffening, step_s] : {std::pair{1.0, 2e-7}, std::pair{0.1, 5e-8}, std::pair{0.01, 1e-8}}) {
      SimSettings settings = hertz_settings(false);
      settings.elastic()->contact.hertz_constant_m_per_N2_3 = 3.86e-8 * std::pow(0.475, -0.115) * stiffening;
      settings.elastic()->contact.restitution = e;
      settings.make_inertial().force_time_step_s = step_s;
      settings.approach_distance_m = 0.005;
      settings.run_out_time_s = 0.001;
      const SimulationResult r = run(square, settings);
      ASSERT_TRUE(r.impact_found());
      ratio = r.impulse_Ns() / plastic_Ns;
      std::printf("e %.1f, G x %g, step %g s: pulse %.4f N s = %.6f x the plastic jump (1 + e = %.1f); %s\n", e,
                  stiffening, step_s, r.impulse_Ns(), ratio, 1.0 + e, r.verdict.ok ? "ok" : r.verdict.reason.c_str());
      EXPECT_TRUE(r.verdict.ok) << r.verdict.reason;
    }
    // The stiffest: the 1e-3 for the plastic limit (measured
    // 1.2e-5); e = 0.5 still loses 4.6e-3 to the static load's share (as
    // restitution 1 does at this stiffness, 1.4e-3 of twice the jump).
    EXPECT_NEAR(ratio, 1.0 + e, e == 0.0 ? 1e-3 : 1e-2);
  }
}

// Zero speed gives the static load: Jenkins's P1 - P0 and P2 - P0 are linear
// in v, so at 0.1 m/s (the slowest speed a scene takes) both lie within
// 0.62 % of P0 (739 N and 337 N on the lumped defaults); the simulated
// forces, which at walking pace stay below Jenkins's, must too.
TEST(ElasticCrossing, AtWalkingPaceTheForcesAreTheStaticLoad) {
  const SimulationResult r = run({"square", 90.0, 0.0}, hertz_settings(true), 0.1);
  ASSERT_TRUE(r.inertial() && r.inertial()->forces && r.inertial()->forces->p2);
  const ForceOutcome& f = *r.inertial()->forces;
  std::printf("0.1 m/s: P1 - P0 = %.1f N, P2 - P0 = %.1f N (Jenkins %.1f N, %.1f N)\n", f.p1_N - f.static_N,
              f.p2->force_N - f.static_N, *f.jenkins.p1_N - f.static_N, *f.jenkins.p2_N - f.static_N);
  EXPECT_LT(f.p1_N - f.static_N, *f.jenkins.p1_N - f.static_N);
  EXPECT_LT(f.p2->force_N - f.static_N, *f.jenkins.p2_N - f.static_N);
  EXPECT_LT(std::abs(f.p1_N / f.static_N - 1.0), 0.0062);
  EXPECT_TRUE(r.verdict.ok) << r.verdict.reason;
}

// A sprung mass on the primary suspension carries the static wheel load, so
// before the joint nothing changes: the contact force is P0 and the sprung
// mass keeps its place relative to the wheel (both move down the slope
// together). After the joint it follows the wheel slowly (1e6 N/m under
// 11.5 t: 1.5 Hz), so the suspension is compressed by the wheel's turn of
// path, beta v = 0.9 m/s at 30 m/s, until P2: by hand it adds about
// k_primary beta v (t_P2 - t_joint) to P2, which a constant load leaves out.
TEST(ElasticCrossing, ASprungMassKeepsTheStaticLoadAndP2) {
  SimSettings sprung = hertz_settings(true);
  sprung.elastic()->vehicle.emplace();
  const SimulationResult with = run({"square", 90.0, 0.0}, sprung);
  const SimulationResult without = run({"square", 90.0, 0.0}, hertz_settings(true));
  ASSERT_TRUE(with.inertial() && with.inertial()->forces && without.inertial() && without.inertial()->forces);
  ASSERT_TRUE(with.inertial()->forces->p2 && without.inertial()->forces->p2);
  const ForceOutcome& f = *with.inertial()->forces;
  const double W = 112.5e3 + 750.0 * 9.81;
  double worst_force = 0.0, worst_relative_motion = 0.0;
  for (std::size_t k = 1; k < with.trajectory.samples.size(); ++k) {
    const WheelSample& s = with.trajectory.samples[k];
    if (s.centre_m.x() > with.prediction().impact_wheel_x_m - 0.02) break;
    worst_force = std::max(worst_force, std::abs(f.contact_force_N[k] / W - 1.0));
    const double wheel_drop_m = s.centre_m.z() - with.trajectory.samples.front().centre_m.z();
    worst_relative_motion = std::max(worst_relative_motion, std::abs(f.track[k].sprung_z_m - wheel_drop_m));
  }
  std::printf(
      "approach: force off P0 by %.3g, sprung mass off the wheel's motion by %.3g m; P2 %.1f N with, %.1f N "
      "without\n",
      worst_force, worst_relative_motion, f.p2->force_N, without.inertial()->forces->p2->force_N);
  EXPECT_LT(worst_force, 1e-9);  // started in equilibrium: round-off only
  EXPECT_LT(worst_relative_motion, 1e-12);
  const double by_hand_N = 1e6 * 0.03 * 30.0 * (f.p2->time_s - with.impact->time_s());
  std::printf("P2 raised by %.1f N; by hand k beta v (t_P2 - t_joint) = %.1f N\n",
              f.p2->force_N - without.inertial()->forces->p2->force_N, by_hand_N);
  // The hand estimate ignores the wheel's sink into the track and the
  // suspension's damper (1e4 N s/m x 0.9 m/s = 9 kN at most, decaying): within a factor 2.
  EXPECT_GT(f.p2->force_N - without.inertial()->forces->p2->force_N, 0.5 * by_hand_N);
  EXPECT_LT(f.p2->force_N - without.inertial()->forces->p2->force_N, 2.0 * by_hand_N);
  EXPECT_TRUE(with.verdict.ok) << with.verdict.reason;
}

// A run whose step cannot follow its contact makes energy: a contact 75x
// stiffer than Hertz's (G = 1e-9, K_H ~ 7e10 N/m, omega ~ 4.5e4 rad/s on the
// 36 kg rail mass) at 6e-5 s, omega dt = 2.7, beyond velocity Verlet's
// stable 2 (at 2e-5 s, omega dt = 0.9, the old semi-implicit Euler had made
// energy already; Verlet's does not grow there). It must say so, not report a P1.
TEST(ElasticCrossing, ARunThatMakesEnergyIsSuspect) {
  SimSettings settings = hertz_settings(true);
  settings.elastic()->contact.hertz_constant_m_per_N2_3 = 1e-9;
  settings.make_inertial().force_time_step_s = 6e-5;
  const SimulationResult r = run({"square", 90.0, 0.0}, settings, 50.0);
  ASSERT_TRUE(r.inertial() && r.inertial()->forces);
  std::printf("verdict: %s\n", r.verdict.reason.c_str());
  EXPECT_FALSE(r.verdict.ok);
  EXPECT_NE(r.verdict.reason.find("energy grew"), std::string::npos) << r.verdict.reason;
}

// A wheel crossing a shallow dip (beta 0.0109) bears on both rail ends at
// once with their patches overlapping (rail_end_patch_share.h): the
// spanning contact's force, a share s of Hertz's at the penetration less
// what the other load presses, is no potential's gradient, and the energy
// booked there (s E_H + F p / 2) moved 0.55 J more than the force's work
// in the 0.2 ms both bore, which the balance kept: 6.45e-3 of its scale
// (0.613 J of 95.1 J) at every step from 4e-6 to 1.25e-7 s (step-free: the
// model's, not the stepping's). That work is booked now
// (elastic_crossing_run.cpp, contact_stage). Measured with it: 4.4e-5 at
// the default step, 2.2e-5 at 2.5e-7 s; on 90 seeded random discrete-track
// scenes (three seeds, both rails) undamped at most 7.2e-5. 2.5e-4 allowed:
// 3.5 times the random scenes' largest, 26 times below the old value. The
// scene is the worst of seed 1's (docs/forces.md, "Where the balance's
// tail came from"): a free hinge on softer supports, 25.2 m/s.
TEST(ElasticCrossing, TheEnergyBalanceClosesWhereBothRailEndsBearWithOverlappingPatches) {
  JointParams joint;
  joint.theta_rad = 55.3 * kPi / 180.0;
  joint.beta_rad = 0.0109;
  WheelParams wheel;
  wheel.lateral_m = -0.0045;
  wheel.width_m = 0.0;
  wheel.speed_m_per_s = 25.2;
  SimSettings settings;
  settings.make_inertial().wheel_load_N = 112.5e3;
  DiscreteTrackSettings& track =
      settings.make_inertial().contact.emplace<ElasticCrossingSettings>().discrete_track.emplace();
  track.support.pad_stiffness_N_per_m = 2.75e8;
  track.support.ballast_stiffness_N_per_m = 5.97e7;
  track.joint_bending_stiffness_N_m_per_rad = 0.0;
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, settings));
  const SimulationResult r = simulate_crossing(joint, wheel, settings);
  ASSERT_TRUE(r.inertial() && r.inertial()->forces);
  const ForceOutcome& f = *r.inertial()->forces;
  std::printf("energy surplus %.4g J of %.4g J (%.3g); P1 %.1f N\n", f.energy_surplus_J, f.energy_scale_J,
              f.energy_surplus_J / f.energy_scale_J, f.p1_N);
  EXPECT_LT(f.energy_surplus_J, 2.5e-4 * f.energy_scale_J);
  // Its P1 is suspect for that very work (self_check.cpp), not for spanning at P1.
  EXPECT_FALSE(r.verdict.ok);
  EXPECT_NE(r.verdict.reason.find("merged-patch law"), std::string::npos) << r.verdict.reason;
  EXPECT_EQ(r.verdict.reason.find("both rail ends bear at P1"), std::string::npos) << r.verdict.reason;
}

// A damped force run on the discrete track (Euler rail, continuous; the
// defaults' wheel and a thin disc, 112.5 kN), stepped at `step_s`.
struct DampedScene {
  double theta_deg, beta, lateral_m, speed_m_per_s, restitution;
  std::optional<double> pad_N_per_m, ballast_N_per_m;
};
SimulationResult damped_discrete_run(const DampedScene& c, double step_s) {
  JointParams joint;
  joint.theta_rad = c.theta_deg * kPi / 180.0;
  joint.beta_rad = c.beta;
  WheelParams wheel;
  wheel.lateral_m = c.lateral_m;
  wheel.width_m = 0.0;
  wheel.speed_m_per_s = c.speed_m_per_s;
  SimSettings settings;
  settings.make_inertial().wheel_load_N = 112.5e3;
  settings.make_inertial().force_time_step_s = step_s;
  ElasticCrossingSettings& elastic = settings.make_inertial().contact.emplace<ElasticCrossingSettings>();
  elastic.contact.restitution = c.restitution;
  DiscreteTrackSettings& track = elastic.discrete_track.emplace();
  if (c.pad_N_per_m) track.support.pad_stiffness_N_per_m = *c.pad_N_per_m;
  if (c.ballast_N_per_m) track.support.ballast_stiffness_N_per_m = *c.ballast_N_per_m;
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, settings));
  return simulate_crossing(joint, wheel, settings);
}

// A strongly damped contact (e 0.219, Hunt and Crossley's alpha 4.46,
// impact rate 0.82 m/s: c = alpha E / v0 up to 1.7e6 N s/m) on the rail's
// nodes (4.5 kg, shared with the stencil's weights): c dt / m under the
// contact up to 1.05 at the default step. The damper was taken at the
// rate predicted from the last step, which a damper survives only for
// c dt / m < 1 (velocity Verlet with the rate predicted: the state (v, a)
// has an eigenvalue -1 there); the run went unstable after the pulse
// (suspect: energy +28.7 J, 8.5e-2 of its scale; P1 493.0 kN, +55 %), and
// was vouched at 3e-6 s. Taken implicitly over the step
// (implicit_contact_damper.h) it is the trapezoidal rule, stable at any c.
// Measured: P1 318373.8 N at 4e-6 s against 318375.1 N at 1e-6 s (4e-6;
// 318376.5 N at 2.5e-7 s), surplus 0. 5e-5 allowed on P1, about ten times
// that; 1e-5 on the surplus (undamped discrete runs close to 7.2e-5 at
// most, this one to 0), 8,000 times below the old. One of 20 seeded
// crossings (scripts/force_convergence_random.py --damped, seed 2).
TEST(ElasticCrossing, AStronglyDampedContactOnTheDiscreteTrackIsStableAtTheDefaultStep) {
  const DampedScene scene{82.425, 0.03103, 0.00218, 26.53, 0.219, {}, {}};
  const SimulationResult r = damped_discrete_run(scene, 4e-6);
  const SimulationResult fine = damped_discrete_run(scene, 1e-6);
  ASSERT_TRUE(r.inertial() && r.inertial()->forces && fine.inertial() && fine.inertial()->forces);
  const ForceOutcome& f = *r.inertial()->forces;
  const double p1_fine_N = fine.inertial()->forces->p1_N;
  std::printf("P1 %.1f N at 4e-6 s, %.1f N at 1e-6 s (%.2e); surplus %.3g of the scale; %s\n", f.p1_N, p1_fine_N,
              f.p1_N / p1_fine_N - 1.0, f.energy_surplus_J / f.energy_scale_J, r.verdict.reason.c_str());
  EXPECT_TRUE(r.verdict.ok) << r.verdict.reason;
  EXPECT_NEAR(f.p1_N / p1_fine_N, 1.0, 5e-5);
  EXPECT_LT(f.energy_surplus_J, 1e-5 * f.energy_scale_J);
}

// A damped contact made again late in the run at a small rate: after the
// P1 impact (1.55 m/s) the wheel flies and lands on the far rail end at
// 0.089 m/s, whose Hunt and Crossley damping alpha E / v0 is 17 times the
// first contact's: c dt / m under it up to 2.4 at the default step. Taken
// at the predicted rate the force chattered on and off each 4e-6 s step
// to the run's end (179 flights, the balance 0.158 of its scale: suspect);
// at 1e-6 s the run had one flight and closed to 4.4e-6. Implicit: one
// flight, 5.8e-6 at 4e-6 s. Allowed: that one flight (a landing is
// one); 5e-5 on the surplus, ten times the measured. Seed 2's 76.9 m/s
// continuous scene of the energy studies (docs/forces.md, e 0.5). The run
// is suspect for another reason, a model's and not the stepping's: its
// patches overlapped before P1 (a 0.0117 rad dip), where the merged-patch
// law's own work leaves P1 1.03 % unvouched (self_check.cpp); the chatter's
// reason was the energy balance, which must not be among its reasons.
TEST(ElasticCrossing, ADampedContactMadeAgainAtASmallRateDoesNotChatter) {
  const DampedScene scene{86.87, 0.011697, -0.0078782, 76.92, 0.5, 4.342e8, 7.8878e7};
  const SimulationResult r = damped_discrete_run(scene, 4e-6);
  ASSERT_TRUE(r.inertial() && r.inertial()->forces);
  const ForceOutcome& f = *r.inertial()->forces;
  std::printf("flights %d (%.3g s); surplus %.3g of the scale; P1 %.1f N; %s\n", f.flights, f.flight_time_s,
              f.energy_surplus_J / f.energy_scale_J, f.p1_N, r.verdict.reason.c_str());
  EXPECT_EQ(r.verdict.reason.find("energy grew"), std::string::npos) << r.verdict.reason;
  EXPECT_NE(r.verdict.reason.find("merged-patch law"), std::string::npos) << r.verdict.reason;
  EXPECT_EQ(f.flights, 1);
  EXPECT_LT(f.energy_surplus_J, 5e-5 * f.energy_scale_J);
}

// P2 is the wheel and track mass on the track's stiffness: a rigid track
// has none to give, a step joint no dip for Jenkins's formulas, and a run
// that ends before half the P2 mode's period (33 ms on the default lumped
// track: 2 pi sqrt((750 + 176) kg / 33.3 MN/m)) cannot have seen it (a 5 ms
// run-out picked a ripple of P1's ringing, 12 % low, as "ok").
TEST(ElasticCrossing, P2OnlyWhereATrackModeCanGiveIt) {
  const SimulationResult rigid = run({"square", 90.0, 0.0}, hertz_settings(false));
  ASSERT_TRUE(rigid.inertial() && rigid.inertial()->forces);
  EXPECT_FALSE(rigid.inertial()->forces->p2.has_value());
  EXPECT_FALSE(rigid.inertial()->forces->jenkins.p2_N.has_value());
  EXPECT_FALSE(rigid.inertial()->forces->jenkins.track.has_value());  // no track mass, stiffness or damping
  EXPECT_TRUE(rigid.inertial()->forces->jenkins.p1_N.has_value());

  SimSettings short_run = hertz_settings(true);
  short_run.run_out_time_s = 0.005;
  const SimulationResult cut = run({"square", 90.0, 0.0}, short_run);
  ASSERT_TRUE(cut.inertial() && cut.inertial()->forces && cut.inertial()->forces->p2);
  const double period_s = 2.0 * kPi * std::sqrt((750.0 + 36.12 + 140.0) / (200e6 * 40e6 / 240e6));
  std::printf("P2 mode period %.3f ms (by hand %.3f ms); 5 ms run: %s\n", cut.inertial()->forces->p2->mode_period_s * 1e3,
              period_s * 1e3, cut.verdict.reason.c_str());
  EXPECT_NEAR(cut.inertial()->forces->p2->mode_period_s / period_s, 1.0, 1e-12);
  EXPECT_FALSE(cut.verdict.ok);
  EXPECT_NE(cut.verdict.reason.find("half the P2 mode's period"), std::string::npos) << cut.verdict.reason;

  JointParams step;
  step.kind = JointKind::step;
  WheelParams wheel;
  wheel.lateral_m = 0.0;
  wheel.speed_m_per_s = 30.0;
  const SimSettings settings = hertz_settings(true);
  step.length_m = std::max(1.0, rail_length_needed_m(step, wheel, settings));
  const SimulationResult stepped = simulate_crossing(step, wheel, settings);
  EXPECT_FALSE(stepped.inertial()->forces->jenkins.p1_N.has_value());
  EXPECT_FALSE(stepped.inertial()->forces->jenkins.p2_N.has_value());
}

// A lumped-track force run's contact force at every step against the
// reference model's at the same instant (lumped_track_reference.h): sample k
// carries the force of the state at its time t_k. The remaining difference is
// velocity Verlet's O((omega dt)^2) error at omega ~ 7e3-9e3 rad/s,
// dt = 4e-6 s.
struct ReferenceComparison {
  double worst_N = 0.0;
  double worst_time_s = 0.0;
  double reference_p1_N = 0.0;
};

ReferenceComparison compare_with_reference(const SimulationResult& r) {
  const ForceOutcome& f = *r.inertial()->forces;
  const CrossingModel& m = *r.model;
  std::vector<double> times;
  for (std::size_t k = 1; k < r.trajectory.samples.size(); ++k) times.push_back(r.trajectory.samples[k].time_s);
  const testing_reference::ReferenceHistory h = lumped_reference_history(m, times);
  ReferenceComparison out;
  for (std::size_t k = 1; k < r.trajectory.samples.size(); ++k) {
    const double d = std::abs(f.contact_force_N[k] - h.force_N[k - 1]);
    if (d > out.worst_N) {
      out.worst_N = d;
      out.worst_time_s = h.time_s[k - 1];
    }
    out.reference_p1_N = std::max(out.reference_p1_N, h.force_N[k - 1]);
  }
  return out;
}

// Seeded random lumped-track crossings over the whole range (theta 20-90 deg,
// beta 0.01-0.05, y_w across the head, v 10-80 m/s, thin disc), each against
// the reference: the median, 90th percentile and largest difference over
// P1. Seed 1 was looked at while the force model was written; seed 2 was not
// (the same bound holds for it, docs/forces.md, "Forces on an elastic track").
void random_force_scenes(unsigned seed, int count) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> theta_deg(20.0, 90.0), beta(0.01, 0.05), lateral(-0.018, 0.018),
      speed(10.0, 80.0);
  std::vector<double> errors;
  int vouched = 0;
  for (int i = 0; i < count; ++i) {
    JointParams joint;
    joint.theta_rad = theta_deg(random) * kPi / 180.0;
    joint.beta_rad = beta(random);
    WheelParams wheel;
    wheel.lateral_m = lateral(random);
    wheel.speed_m_per_s = speed(random);
    const SimSettings settings = hertz_settings(true);
    joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, settings));
    const SimulationResult r = simulate_crossing(joint, wheel, settings);
    const ReferenceComparison cmp = compare_with_reference(r);
    const double error = cmp.worst_N / cmp.reference_p1_N;
    errors.push_back(error);
    vouched += r.verdict.ok ? 1 : 0;
    if (!r.verdict.ok) std::printf("  not vouched: %s\n", r.verdict.reason.c_str());
    std::printf(
        "  theta %5.1f deg, beta %.4f, y_w %+6.2f mm, v %4.1f m/s: P1 %8.1f kN, largest difference %.3g of P1\n",
        joint.theta_rad * 180.0 / kPi, joint.beta_rad, wheel.lateral_m * 1e3, wheel.speed_m_per_s,
        r.inertial()->forces->p1_N / 1e3, error);
  }
  std::sort(errors.begin(), errors.end());
  const double median = errors[errors.size() / 2];
  const double p90 = errors[static_cast<std::size_t>(0.9 * static_cast<double>(errors.size() - 1))];
  std::printf("seed %u, %d scenes, %d vouched: largest difference over P1: median %.3g, 90th percentile %.3g, max %.3g\n",
              seed, count, vouched, median, p90, errors.back());
  // The target for every scene: within 1 % of P1.
  EXPECT_LT(errors.back(), 0.01);
}

TEST(ElasticCrossing, RandomLumpedCrossingsAgreeWithTheReference) { random_force_scenes(1, 12); }
TEST(ElasticCrossing, RandomLumpedCrossingsOfAnUnseenSeedAgreeWithTheReference) { random_force_scenes(2, 12); }

class ForceHistory : public ::testing::TestWithParam<ForceCase> {};

// The three crossings against the reference (compare_with_reference).
TEST_P(ForceHistory, AgreesWithTheReferenceOdeWithinOnePercentOfP1) {
  const ForceCase& c = GetParam();
  const SimulationResult r = run(c, hertz_settings(true));
  ASSERT_TRUE(r.inertial() && r.inertial()->forces);
  const ForceOutcome& f = *r.inertial()->forces;
  const ReferenceComparison cmp = compare_with_reference(r);
  std::printf("%s: P1 simulated %.1f N, reference %.1f N (%+.3g %%); largest difference %.1f N (%.3g of P1) at t = %.4f ms\n",
              c.name, f.p1_N, cmp.reference_p1_N, 100.0 * (f.p1_N / cmp.reference_p1_N - 1.0), cmp.worst_N,
              cmp.worst_N / cmp.reference_p1_N, cmp.worst_time_s * 1e3);
  // The target: within 1 % of P1 over the whole crossing.
  EXPECT_LT(cmp.worst_N / cmp.reference_p1_N, 0.01);
  EXPECT_LT(std::abs(f.p1_N / cmp.reference_p1_N - 1.0), 0.01);
  // Energy: what the run holds, less what it started with and the carrier
  // put in, plus what the dampers took, must stay near 0 (it swings by the
  // step's error; measured 6e-4 of M (beta v)^2 / 2 + P0 s0 / 2 here).
  std::printf("energy surplus %.4g J of %.4g J\n", f.energy_surplus_J, f.energy_scale_J);
  EXPECT_LT(f.energy_surplus_J, 0.01 * f.energy_scale_J);
  EXPECT_TRUE(r.verdict.ok) << r.verdict.reason;
}

INSTANTIATE_TEST_SUITE_P(SquareScenario1Scenario2, ForceHistory,
                         ::testing::Values(ForceCase{"square", 90.0, 0.0}, ForceCase{"scenario1", 45.0, 0.0},
                                           ForceCase{"scenario2", 45.0, 0.010}),
                         [](const ::testing::TestParamInfo<ForceCase>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace railjoint
