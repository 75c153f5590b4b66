// The discrete track's force run against the independent Hermite-beam
// reference (hermite_beam_reference.h): the reference first on its own
// (statics against Hetenyi's closed forms, its start and step), then the
// simulation's P1 and P2 against it for continuous rail, joint bars and a
// free hinge (issue 41, item 6: within 1 %).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "sim/crossing_analysis.h"
#include "sim/crossing_model.h"
#include "sim/discrete_track.h"
#include "sim/elastic_crossing_run.h"
#include "sim/force_peaks.h"
#include "sim/simulate_crossing.h"
#include "tests/sim/force_scenes.h"
#include "tests/sim/hermite_beam_reference.h"

namespace railjoint {
namespace {

using testing_reference::HermiteBeam;
using testing_reference::HermiteBeamCrossing;
using testing_reference::HermiteBeamRun;

constexpr double kPi = 3.14159265358979323846;

// Hetenyi (Beams on Elastic Foundation, 1946): a semi-infinite beam on a
// Winkler foundation k [N/m^2], beta = (k / 4 EI)^(1/4), loaded at its end by
// a force P' and a moment M0 that lifts it, sinks there by
// 2 beta / k (P' - beta M0) and turns by 2 beta^2 / k (P' - 2 beta M0).
// A load P on the joint between two such halves: each carries P' = P / 2,
// the joint's spring k_j sees twice the end's turn and pushes back with
// M0 = k_j 2 theta, so M0 = 4 k_j beta^2 P' / (k + 8 k_j beta^3) and
// w = 2 beta / k (P' - beta M0): P beta / k at a free hinge (k_j = 0),
// P beta / (2 k) for continuous rail (k_j -> infinity: M0 = P' / (2 beta)).
double hetenyi_joint_deflection_m(double EI, double k, double P, double k_joint) {
  const double beta = std::pow(k / (4.0 * EI), 0.25);
  const double half = 0.5 * P;
  const double M0 = std::isinf(k_joint) ? half / (2.0 * beta)
                                        : 4.0 * k_joint * beta * beta * half / (k + 8.0 * k_joint * beta * beta * beta);
  return 2.0 * beta / k * (half - beta * M0);
}

struct JointCase {
  const char* name;
  double k_joint;  ///< infinity: continuous rail
};

const JointCase kJoints[] = {{"continuous", INFINITY}, {"joint_bars_1e6", 1e6}, {"free_hinge", 0.0}};

HermiteBeamCrossing with_joint(HermiteBeamCrossing c, double k_joint) {
  c.hinge = !std::isinf(k_joint);
  c.joint_stiffness = c.hinge ? k_joint : 0.0;
  return c;
}

// The reference's statics against Hetenyi with the supports closely spaced
// (0.05 m, each carrying k s, so the foundation is nearly continuous: its
// discreteness, (beta s)^2 ~ 4e-3 of the bending, shows in the fourth
// digit). Measured within 4e-4 for the three joints; 1e-3 allowed.
TEST(HermiteBeamReference, StaticDeflectionMatchesHetenyiOnANearlyContinuousFoundation) {
  HermiteBeamCrossing c;
  c.sleeper_spacing_m = 0.05;
  c.elements_per_bay = 2;
  c.half_length_m = 10.0;
  const double k_per_m = 50e6 / 0.6;  // the defaults' pad and ballast in series, per metre of a 0.6 m bay
  c.pad_stiffness = 1e12;             // the support all in the ballast
  c.ballast_stiffness = k_per_m * c.sleeper_spacing_m;
  const double P = 120e3;
  for (const JointCase& joint : kJoints) {
    const HermiteBeam beam(with_joint(c, joint.k_joint));
    Eigen::VectorXd u = beam.static_state(P, 0.0, true);
    const double w = -beam.deflection_m(u, 0.0, true);
    const double expected = hetenyi_joint_deflection_m(c.bending_stiffness_N_m2, k_per_m, P, joint.k_joint);
    std::printf("%s: reference %.6g mm, Hetenyi %.6g mm (%+.2e)\n", joint.name, w * 1e3, expected * 1e3,
                w / expected - 1.0);
    EXPECT_NEAR(w / expected, 1.0, 1e-3) << joint.name;
  }
}

// The same on the discrete track's own supports (a sleeper every 0.6 m, the
// joint midway between two), continuous rail: Winkler's smeared support is
// stiffer under the joint (mid-span is the softest place), by 0.47 %
// measured, the discrete supports' own effect; within 1 %. (At a hinge the
// smeared foundation is no guide: two sleepers 0.3 m either side carry the
// rail ends nearly as cantilevers, 8-10 % softer than Hetenyi's.)
TEST(HermiteBeamReference, StaticDeflectionOnSleepersIsNearHetenyi) {
  const HermiteBeamCrossing c;
  const double k_per_m = 200e6 * 40e6 / 240e6 / 0.6;
  const HermiteBeam beam(c);
  const double w = -beam.deflection_m(beam.static_state(120e3, 0.0, true), 0.0, true);
  const double expected = hetenyi_joint_deflection_m(c.bending_stiffness_N_m2, k_per_m, 120e3, INFINITY);
  std::printf("continuous rail on sleepers: reference %.6g mm, Hetenyi (smeared) %.6g mm (%+.3f %%)\n", w * 1e3,
              expected * 1e3, 100 * (w / expected - 1.0));
  EXPECT_GT(w, expected);
  EXPECT_NEAR(w / expected, 1.0, 0.01);
}

// The simulation's static line against the reference's, the load at points
// near the joint (where the interpolation meets the hinge) and away from it:
// the largest difference in the deflection under the load.
double worst_static_difference(double k_joint, bool print) {
  DiscreteTrackSettings t;
  if (!std::isinf(k_joint)) t.joint_bending_stiffness_N_m_per_rad = k_joint;
  DiscreteTrack track(t, 8.0);
  const HermiteBeam beam(with_joint(HermiteBeamCrossing{}, k_joint));
  const double P = 120e3;
  double worst = 0.0;
  for (double x = -0.60; x <= 0.6001; x += 0.0125) {
    track.rest_under(P, x);
    const double simulated = track.deflection_m(x);
    const double reference = beam.deflection_m(beam.static_state(P, x, x <= 0.0), x, x <= 0.0);
    worst = std::max(worst, std::abs(simulated / reference - 1.0));
    if (print && std::abs(std::remainder(x, 0.15)) < 1e-6) {
      std::printf("  x %+.3f m: sim %.5f mm, reference %.5f mm (%+.3f %%)\n", x, simulated * 1e3, reference * 1e3,
                  100 * (simulated / reference - 1.0));
    }
  }
  return worst;
}

// The discrete track's static deflection under a load anywhere within a bay
// of the joint, against the reference's exact beam: the rigid-element rail
// (its fourth difference, (h beta)^2 / 12 ~ 7e-4) and its interpolation
// between nodes. Read with each rail's own nodes at a hinge: measured within
// 0.25 % for the three joints (a stencil across the hinge had been 2.5 % off
// with joint bars and 3.0 % at a free hinge); 1 % allowed.
TEST(HermiteBeamReference, TheDiscreteTracksStaticLineNearTheJointMatchesTheExactBeam) {
  for (const JointCase& joint : kJoints) {
    std::printf("%s:\n", joint.name);
    const double worst = worst_static_difference(joint.k_joint, true);
    std::printf("%s: largest difference %.3f %%\n", joint.name, 100 * worst);
    EXPECT_LT(worst, 0.01) << joint.name;
  }
}

// discrete_track_model (force_scenes.h) at speed v, the hinge k_joint
// (infinite: continuous rail).
CrossingModel discrete_model(double v, double k_joint, double approach_m) {
  return discrete_track_model(v, std::isinf(k_joint) ? std::nullopt : std::optional<double>(k_joint), approach_m);
}

ForceOutcome simulated_forces(const CrossingModel& m) {
  const SimulationResult r = analyse_inertial_crossing(std::make_shared<const CrossingModel>(m), run_elastic_crossing(m));
  return *r.inertial()->forces;
}

struct Comparison {
  double sim_p1_N, sim_p2_N, ref_p1_N, ref_p2_N;
  ForceOutcome sim;
  HermiteBeamRun ref;
  double p1_error() const { return sim_p1_N / ref_p1_N - 1.0; }
  double p2_error() const { return sim_p2_N / ref_p2_N - 1.0; }
};

// The reference on the simulation's wheel, contact and track, started
// `reference_start_m` before the joint, run to where the simulation ends; its
// P1 and P2 picked as the simulation's are (force_peaks.h, the same P2 mode
// period: the measures' definition, not the mechanics under test).
// The reference crossing on the simulation model's wheel, contact and dip.
HermiteBeamCrossing reference_of(const CrossingModel& m, double k_joint) {
  HermiteBeamCrossing c = with_joint(HermiteBeamCrossing{}, k_joint);
  c.speed_m_per_s = m.wheel.speed_m_per_s;
  c.wheel_mass_kg = m.wheel.mass_kg;
  c.radius_m = m.wheel.radius_m;
  c.wheel_load_N = m.settings.inertial()->wheel_load_N;
  c.hertz_constant = m.hertz_constant_m_per_N2_3;
  c.half_dip_slope = std::tan(0.5 * m.joint.beta_rad);
  c.gravity = kStandardGravity_m_per_s2;
  return c;
}

// Its beam's ends beyond the run [m]: 16 decay lengths (1 / 1.22 m), as the
// simulation's (DiscreteTrack::half_length_for_run_m: a free hinge's P1 at
// 20 m/s feels ends 6 or 12 decay lengths out, FreeHingeAt20AgainstTheBeamsLength).
double reference_end_clearance_m(double k_joint) {
  (void)k_joint;
  return 16.0 / 1.22;
}

Comparison compare(double v, double k_joint, double approach_m, double reference_start_m, double reference_step_s) {
  const CrossingModel m = discrete_model(v, k_joint, approach_m);
  const ForceOutcome sim = simulated_forces(m);
  HermiteBeamCrossing c = reference_of(m, k_joint);
  c.start_x_m = -reference_start_m;
  c.end_x_m = m.start.centre_m.x() + v * m.end_time_s;
  c.half_length_m = std::max(reference_start_m, c.end_x_m) + reference_end_clearance_m(k_joint);
  c.step_s = reference_step_s;
  const HermiteBeamRun ref = HermiteBeam(c).run();
  const double static_N = c.wheel_load_N + c.wheel_mass_kg * c.gravity;
  const ForcePeaks peaks =
      pick_force_peaks(ref.time_s, ref.force_z_N, static_N, kP2CutoffFrequency_Hz, sim.p2->mode_period_s);
  return {sim.p1_N, sim.p2->force_N, peaks.p1_N, peaks.p2_N, sim, ref};
}

// The reference vouches for itself: a start 1.5x further out and half the
// step move its P1 and P2 at a free hinge at 50 m/s by far less than the
// 1 % the simulation is held to (1e-3 allowed; a start 1 m out, not 2.5 m,
// was 1.8e-3 off in P1).
TEST(HermiteBeamReference, ItsStartAndStepDoNotMatter) {
  const CrossingModel m = discrete_model(50.0, 0.0, 0.05);
  const auto run_with = [&](double start_m, double step_s) {
    HermiteBeamCrossing c = with_joint(HermiteBeamCrossing{}, 0.0);
    c.hertz_constant = m.hertz_constant_m_per_N2_3;
    c.start_x_m = -start_m;
    c.end_x_m = 0.5;
    c.half_length_m = start_m + 5.0;
    c.step_s = step_s;
    const HermiteBeamRun r = HermiteBeam(c).run();
    return pick_force_peaks(r.time_s, r.force_z_N, c.wheel_load_N + c.wheel_mass_kg * c.gravity, kP2CutoffFrequency_Hz,
                            0.02);
  };
  const ForcePeaks base = run_with(2.5, 4e-6), further = run_with(3.75, 4e-6), finer = run_with(2.5, 2e-6);
  std::printf("reference at a free hinge, 50 m/s: P1 %.1f N, P2 %.1f N; started 1.5 m out %+.2e, %+.2e; "
              "half the step %+.2e, %+.2e\n",
              base.p1_N, base.p2_N, further.p1_N / base.p1_N - 1, further.p2_N / base.p2_N - 1,
              finer.p1_N / base.p1_N - 1, finer.p2_N / base.p2_N - 1);
  EXPECT_NEAR(further.p1_N / base.p1_N, 1.0, 1e-3);
  EXPECT_NEAR(further.p2_N / base.p2_N, 1.0, 1e-3);
  EXPECT_NEAR(finer.p1_N / base.p1_N, 1.0, 1e-3);
  EXPECT_NEAR(finer.p2_N / base.p2_N, 1.0, 1e-3);
}

// The simulation against the reference at 50 m/s, the default start, for the
// three joints: P1 and P2 within 1 % (issue 41's target).
TEST(HermiteBeamReference, TheSimulationsP1AndP2MatchTheReferenceAt50) {
  for (const JointCase& joint : kJoints) {
    const Comparison r = compare(50.0, joint.k_joint, SimSettings{}.approach_distance_m, 2.5, 4e-6);
    std::printf("%s 50 m/s: P1 sim %.1f ref %.1f kN (%+.2f %%), P2 sim %.1f ref %.1f kN (%+.2f %%)\n", joint.name,
                r.sim_p1_N / 1e3, r.ref_p1_N / 1e3, 100 * r.p1_error(), r.sim_p2_N / 1e3, r.ref_p2_N / 1e3,
                100 * r.p2_error());
    EXPECT_NEAR(r.p1_error(), 0.0, 0.01) << joint.name;
    EXPECT_NEAR(r.p2_error(), 0.0, 0.01) << joint.name;
  }
}

// The start does not matter: sim.approach_distance from its default to 3 m
// moves a free hinge's P1 and P2 at 50 m/s by less than 1 % (issue 41; a
// start 5 cm before the hinge had read P1 12 % high). The discrete track
// starts at least DiscreteTrack::start_lead_m out, so the default and 1 m
// are one run; 3 m is a longer one.
TEST(HermiteBeamReference, TheStartDoesNotMatterAtAFreeHinge) {
  const ForceOutcome base = simulated_forces(discrete_model(50.0, 0.0, SimSettings{}.approach_distance_m));
  const ForceOutcome far = simulated_forces(discrete_model(50.0, 0.0, 3.0));
  std::printf("free hinge, 50 m/s: default start P1 %.1f P2 %.1f kN; 3 m out P1 %.1f (%+.3f %%) P2 %.1f kN (%+.3f %%)\n",
              base.p1_N / 1e3, base.p2->force_N / 1e3, far.p1_N / 1e3, 100 * (far.p1_N / base.p1_N - 1),
              far.p2->force_N / 1e3, 100 * (far.p2->force_N / base.p2->force_N - 1));
  EXPECT_NEAR(far.p1_N / base.p1_N, 1.0, 0.01);
  EXPECT_NEAR(far.p2->force_N / base.p2->force_N, 1.0, 0.01);
}

// The supports' forces (issue 41, item 1 on the discrete track): the largest
// rail-seat (pad) and ballast forces over the supports near the joint against
// the reference's largest over all its supports (plus the weights each
// carries, mu s g and + m_s g, as the simulation reports them), at 50 m/s.
// The pads' dampers read the rail's rate at the sleeper, where the two
// models' rails differ most (rigid links against cubics): 2 % allowed,
// measured below. The peak is at one of the two sleepers beside the joint.
TEST(HermiteBeamReference, TheSupportsPeakForcesMatchTheReference) {
  const double mu_s_g = 60.2 * 0.6 * kStandardGravity_m_per_s2, sleeper_g = 140.0 * kStandardGravity_m_per_s2;
  for (const JointCase& joint : kJoints) {
    const Comparison r = compare(50.0, joint.k_joint, SimSettings{}.approach_distance_m, 2.5, 4e-6);
    ASSERT_TRUE(r.sim.support && r.sim.support->rail_seat_peak_x_m);
    const TrackSupportOutcome& s = *r.sim.support;
    const double ref_seat_N = *std::max_element(r.ref.peak_pad_N.begin(), r.ref.peak_pad_N.end()) + mu_s_g;
    const double ref_ballast_N =
        *std::max_element(r.ref.peak_ballast_N.begin(), r.ref.peak_ballast_N.end()) + mu_s_g + sleeper_g;
    std::printf("%s 50 m/s: rail seat peak %.1f kN at x %+.2f m (reference %.1f kN, %+.2f %%), ballast %.1f kN at "
                "x %+.2f m (reference %.1f kN, %+.2f %%), rail-seat P2 %.1f kN, static %.1f kN\n",
                joint.name, s.rail_seat_peak_N / 1e3, *s.rail_seat_peak_x_m, ref_seat_N / 1e3,
                100 * (s.rail_seat_peak_N / ref_seat_N - 1), s.ballast_peak_N / 1e3, *s.ballast_peak_x_m,
                ref_ballast_N / 1e3, 100 * (s.ballast_peak_N / ref_ballast_N - 1), s.p2_rail_seat_N / 1e3,
                s.rail_seat_static_N / 1e3);
    EXPECT_NEAR(std::abs(*s.rail_seat_peak_x_m), 0.3, 1e-9) << joint.name;
    EXPECT_NEAR(s.rail_seat_peak_N / ref_seat_N, 1.0, 0.02) << joint.name;
    EXPECT_NEAR(s.ballast_peak_N / ref_ballast_N, 1.0, 0.02) << joint.name;
    EXPECT_GT(s.p2_rail_seat_N, s.rail_seat_static_N) << joint.name;
  }
}

// Studies (ctest label study: HermiteBeamStudy.*).

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The table: the simulation against the reference for the three joints at
// 20, 50 and 80 m/s; every P1 and P2 within 1 % (issue 41's target).
// Measured: |P1 diff| median 0.12 %, max 0.19 %; |P2 diff| median 0.07 %,
// max 0.13 %. (A free hinge at 20 m/s was -1.33 % off while both beams'
// ends lay 6 decay lengths past the run: both P1s felt them, the
// simulation's from 6.6 m, the reference's from 7.4 m;
// FreeHingeAt20AgainstTheBeamsLength.)
TEST(HermiteBeamStudy, SpeedsAndJointsAgainstTheReference) {
  std::vector<double> p1, p2;
  std::printf("| joint | v [m/s] | P1 sim [kN] | P1 ref [kN] | P1 diff | P2 sim [kN] | P2 ref [kN] | P2 diff |\n"
              "|---|---|---|---|---|---|---|---|\n");
  for (const JointCase& joint : kJoints) {
    for (double v : {20.0, 50.0, 80.0}) {
      const Comparison r = compare(v, joint.k_joint, SimSettings{}.approach_distance_m, 2.5, 2e-6);
      std::printf("| %s | %.0f | %.1f | %.1f | %+.2f %% | %.1f | %.1f | %+.2f %% |\n", joint.name, v, r.sim_p1_N / 1e3,
                  r.ref_p1_N / 1e3, 100 * r.p1_error(), r.sim_p2_N / 1e3, r.ref_p2_N / 1e3, 100 * r.p2_error());
      p1.push_back(std::abs(r.p1_error()));
      p2.push_back(std::abs(r.p2_error()));
      EXPECT_NEAR(r.p1_error(), 0.0, 0.01) << joint.name << " " << v;
      EXPECT_NEAR(r.p2_error(), 0.0, 0.01) << joint.name << " " << v;
    }
  }
  std::printf("|P1 diff|: median %.2f %%, max %.2f %%; |P2 diff|: median %.2f %%, max %.2f %%\n", 100 * median(p1),
              100 * *std::max_element(p1.begin(), p1.end()), 100 * median(p2), 100 * *std::max_element(p2.begin(), p2.end()));
}

// sim.approach_distance from the default to 3 m, each joint at 50 m/s: P1
// and P2 move less than 1 % from the default's.
TEST(HermiteBeamStudy, ApproachDistance) {
  for (const JointCase& joint : kJoints) {
    const ForceOutcome base = simulated_forces(discrete_model(50.0, joint.k_joint, SimSettings{}.approach_distance_m));
    for (double approach : {0.05, 0.5, 1.0, 2.0, 3.0}) {
      const ForceOutcome f = simulated_forces(discrete_model(50.0, joint.k_joint, approach));
      std::printf("| %s | %.2f m | P1 %.1f kN (%+.3f %%) | P2 %.1f kN (%+.3f %%) |\n", joint.name, approach,
                  f.p1_N / 1e3, 100 * (f.p1_N / base.p1_N - 1), f.p2->force_N / 1e3,
                  100 * (f.p2->force_N / base.p2->force_N - 1));
      EXPECT_NEAR(f.p1_N / base.p1_N, 1.0, 0.01);
      EXPECT_NEAR(f.p2->force_N / base.p2->force_N, 1.0, 0.01);
    }
  }
}

// The run-out (0.02, 0.03, 0.1 s) and half the step on both elastic tracks,
// at a free hinge and on the lumped track, 50 m/s: P1 and P2 within 1 %.
TEST(HermiteBeamStudy, RunOutAndStepOnBothTracks) {
  for (bool discrete : {true, false}) {
    const auto run = [&](double run_out_s, double step_scale) {
      JointParams joint;
      joint.theta_rad = kPi / 2;
      WheelParams wheel;
      wheel.lateral_m = 0.0;
      wheel.speed_m_per_s = 50.0;
      SimSettings settings;
      InertialSettings& inertial = settings.make_inertial();
      ElasticCrossingSettings& elastic = inertial.contact.emplace<ElasticCrossingSettings>();
      if (discrete) {
        elastic.discrete_track.emplace().joint_bending_stiffness_N_m_per_rad = 0.0;
      } else {
        elastic.track.emplace();
      }
      inertial.force_time_step_s *= step_scale;
      settings.run_out_time_s = run_out_s;
      joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, settings));
      return simulated_forces(build_crossing_model(joint, wheel, settings));
    };
    const ForceOutcome base = run(0.02, 1.0);
    for (const auto& [run_out_s, scale] : std::vector<std::pair<double, double>>{{0.03, 1.0}, {0.1, 1.0}, {0.02, 0.5}}) {
      const ForceOutcome f = run(run_out_s, scale);
      std::printf("| %s | run-out %.2f s, step x %.1f | P1 %.1f kN (%+.3f %%) | P2 %.1f kN (%+.3f %%) |\n",
                  discrete ? "discrete, free hinge" : "lumped", run_out_s, scale, f.p1_N / 1e3,
                  100 * (f.p1_N / base.p1_N - 1), f.p2->force_N / 1e3, 100 * (f.p2->force_N / base.p2->force_N - 1));
      EXPECT_NEAR(f.p1_N / base.p1_N, 1.0, 0.01);
      EXPECT_NEAR(f.p2->force_N / base.p2->force_N, 1.0, 0.01);
    }
  }
}

// Issue 41: a free hinge at 20 m/s, whose P1 is a broad hump 6.4 ms after
// the impact. Its P1 moved with the start because the start set the beam's
// length (the run's reach plus 6 static decay lengths, in whole bays): the
// hump is slow (near the track's 75 Hz cut-on, where the rail's response
// reaches much further than its static line) and felt free ends 6.6 m out
// (3.0 and 3.3 m starts, the same bays, agreed to 3e-6; damping the ends'
// last 3 or 6 decay lengths did not remove it, a longer beam did). The reference on beams of growing length (its
// own start 2.5 m out) and the simulation from starts of 1, 3 and 5 m
// (its beam now 16 decay lengths past the run).
TEST(HermiteBeamStudy, FreeHingeAt20AgainstTheBeamsLength) {
  const CrossingModel m = discrete_model(20.0, 0.0, SimSettings{}.approach_distance_m);
  const double static_N = m.settings.inertial()->wheel_load_N + m.wheel.mass_kg * kStandardGravity_m_per_s2;
  const ForceOutcome sim = simulated_forces(m);
  std::vector<double> reference_p1;
  for (double half_length_m : {7.4, 10.0, 13.0, 16.0, 20.0}) {
    HermiteBeamCrossing c = reference_of(m, 0.0);
    c.start_x_m = -2.5;
    c.end_x_m = 0.45;
    c.half_length_m = half_length_m;
    c.step_s = 4e-6;
    const HermiteBeamRun ref = HermiteBeam(c).run();
    const ForcePeaks peaks = pick_force_peaks(ref.time_s, ref.force_z_N, static_N, kP2CutoffFrequency_Hz,
                                              sim.p2->mode_period_s);
    std::printf("| reference, beam +-%.1f m | P1 %.2f kN | P2 %.2f kN |\n", half_length_m, peaks.p1_N / 1e3,
                peaks.p2_N / 1e3);
    reference_p1.push_back(peaks.p1_N);
  }
  // Measured with the sum of two springs 249.92, 248.89, 248.21, 248.26,
  // 248.26 kN: settled from 13 m (2e-4); with the two rail ends' contacts
  // coupled 251.92, 251.20, 250.24, 250.20, 250.21 kN. The simulation's
  // default against the longest: 1.1e-3 while its beam reached 12 decay
  // lengths past the run (the ends' reflections), now 16: measured
  // -2.7e-4 (250.14 kN); 6e-4 allowed (the two beams' end reflections,
  // each up to 1.5e-4 over ends 13-30 m out, and the rigid-element rail).
  EXPECT_NEAR(reference_p1[3] / reference_p1[4], 1.0, 1e-3);
  EXPECT_NEAR(sim.p1_N / reference_p1[4], 1.0, 6e-4);
  std::vector<double> p1;
  for (double start_m : {1.0, 3.0, 5.0}) {
    const ForceOutcome f = simulated_forces(discrete_model(20.0, 0.0, start_m));
    std::printf("| simulation, start %.0f m | P1 %.2f kN | P2 %.2f kN |\n", start_m, f.p1_N / 1e3, f.p2->force_N / 1e3);
    p1.push_back(f.p1_N);
  }
  const auto [lo, hi] = std::minmax_element(p1.begin(), p1.end());
  std::printf("simulation's P1 over starts of 1, 3, 5 m: spread %.3f %%\n", 100 * (*hi / *lo - 1));
  // Measured 4.4e-5 (250.142, 250.131, 250.137 kN; 1.1e-3 with 12 decay
  // lengths, each start's beam ending elsewhere); 3e-4 allowed, as
  // DiscreteTrack.AFreeHingesP1At20HoldsFromStartsOf1To5m.
  EXPECT_LT(*hi / *lo - 1, 3e-4);
}

// The crests of a contact force history sampled every `step_s` at speed v:
// the local maxima over +-2.5 mm of travel (the ring's crests lie 25-32 mm
// apart at 50 m/s) above P0 + 0.3 (largest - P0), each at its parabola's
// vertex, in order [N].
std::vector<double> crests_N(const std::vector<double>& force_N, double static_N, double step_s, double v) {
  const std::size_t half = std::max<std::size_t>(1, static_cast<std::size_t>(2.5e-3 / (v * step_s)));
  const double largest_N = *std::max_element(force_N.begin(), force_N.end());
  std::vector<double> out;
  for (std::size_t i = half; i + half < force_N.size(); ++i) {
    const double f = force_N[i];
    if (f <= static_N + 0.3 * (largest_N - static_N)) continue;
    const auto from = force_N.begin() + static_cast<long>(i - half);
    if (f < *std::max_element(from, from + static_cast<long>(2 * half + 1))) continue;
    const double a = force_N[i - 1], c = force_N[i + 1], curvature = a - 2.0 * f + c;
    out.push_back(curvature < 0.0 ? f - 0.125 * (a - c) * (a - c) / curvature : f);
  }
  return out;
}

// Why P1 converges irregularly with the rail's grid (docs/forces.md, "The
// rail's grid"). P1 is the largest force in its window (force_peaks.h), and
// on the square joint at 50 m/s that is not the impact's first crest but a
// later crest of the wheel-on-rail ring riding up the P2 hump (the third on
// continuous rail, the fourth at a free hinge; on seeded random crossings a
// crest 1.3-2.1 ms after the impact in 18 of 20). What the grid does to it is
// the ring's phase (the chain's O(h^2) dispersion, added up over the crests)
// on a crest's slope: small, of changing sign, and the pick can change crest
// with the grid, so its observed order scatters. The first crest converges
// at second order against this reference (cubic elements, consistent mass,
// an exact hinge: not the chain's grid), and at 8 nodes a bay it is 8-12x
// further off than the largest. Measured (reference at 8 and 16 elements a
// bay 1.5e-4 apart): continuous first crest -7.3e-3, -2.2e-3, -9.0e-4 at 8,
// 16, 32 nodes a bay, the largest -6.3e-4, -3.1e-4, -2.3e-4; free hinge
// +1.41e-2, +2.9e-3, +4.5e-4 and -1.8e-3, -2.7e-4, -1.6e-4. The 16/32
// extrapolation of the first crest lands 3.7-4.6e-4 below the reference on
// both (the two models' contacts and rails differ by that), 1e-3 allowed.
// A read-out with zero tangents between nodes (first order) fails it.
TEST(HermiteBeamStudy, TheFirstCrestConvergesWithTheGridWhereTheLargestForceIsALaterCrest) {
  const double v = 50.0;
  for (const JointCase& joint : {kJoints[0], kJoints[2]}) {
    const CrossingModel base = discrete_model(v, joint.k_joint, SimSettings{}.approach_distance_m);
    const double static_N = base.settings.inertial()->wheel_load_N + base.wheel.mass_kg * kStandardGravity_m_per_s2;
    HermiteBeamCrossing c = reference_of(base, joint.k_joint);
    c.start_x_m = -2.5;
    c.end_x_m = 0.6;  // past the crests P1 is picked from
    c.half_length_m = 2.5 + reference_end_clearance_m(joint.k_joint);
    c.step_s = 2e-6;
    const HermiteBeamRun ref = HermiteBeam(c).run();
    const std::vector<double> ref_crests = crests_N(ref.force_z_N, static_N, c.step_s, v);
    ASSERT_GE(ref_crests.size(), 4u) << joint.name;
    const double ref_first_N = ref_crests.front();
    const double ref_largest_N = *std::max_element(ref_crests.begin(), ref_crests.end());
    std::vector<double> first_error, largest_error;
    for (const auto& [nodes, step_s] : {std::pair{8, 4e-6}, std::pair{16, 1e-6}, std::pair{32, 2.5e-7}}) {
      DiscreteTrackSettings track;
      track.nodes_per_bay = nodes;
      if (!std::isinf(joint.k_joint)) track.joint_bending_stiffness_N_m_per_rad = joint.k_joint;
      const ForceOutcome sim =
          simulated_forces(discrete_track_model(v, track, SimSettings{}.approach_distance_m, step_s));
      const std::vector<double> crests = crests_N(sim.contact_force_N, static_N, step_s, v);
      ASSERT_GE(crests.size(), 4u) << joint.name << " " << nodes;
      const std::size_t largest =
          static_cast<std::size_t>(std::max_element(crests.begin(), crests.end()) - crests.begin());
      first_error.push_back(crests.front() / ref_first_N - 1.0);
      largest_error.push_back(sim.p1_N / ref_largest_N - 1.0);
      std::printf("%s, %d nodes a bay: first crest %.2f kN (reference %.2f, %+.2e), P1 %.2f kN = crest %zu "
                  "(reference %.2f, %+.2e)\n",
                  joint.name, nodes, crests.front() / 1e3, ref_first_N / 1e3, first_error.back(), sim.p1_N / 1e3,
                  largest + 1, ref_largest_N / 1e3, largest_error.back());
      EXPECT_GE(largest, 2u) << joint.name << " " << nodes;  // P1 is a later crest
      EXPECT_NEAR(crests[largest] / sim.p1_N, 1.0, 1e-4) << joint.name << " " << nodes;  // the same peak as P1's pick
    }
    // Second order: 3.3x and 2.5x (continuous), 4.9x and 6.5x (hinge) per
    // halving measured; 2.5x and 2x asked (the models' ~4e-4 offset shows at
    // 32; the zero-tangent read-out gave 0.85x and 0.27x).
    EXPECT_GT(std::abs(first_error[0]), 2.5 * std::abs(first_error[1])) << joint.name;
    EXPECT_GT(std::abs(first_error[1]), 2.0 * std::abs(first_error[2])) << joint.name;
    const double extrapolated = first_error[2] + (first_error[2] - first_error[1]) / 3.0;
    std::printf("%s: first crest's 16/32 extrapolation %+.2e off the reference\n", joint.name, extrapolated);
    EXPECT_NEAR(extrapolated, 0.0, 1e-3) << joint.name;
    // At 8 nodes a bay the first crest is off by several times P1's error.
    EXPECT_GT(std::abs(first_error[0]), 4.0 * std::abs(largest_error[0])) << joint.name;
  }
}

}  // namespace
}  // namespace railjoint
