// The force run's time integration (vertical_mass.h, elastic_crossing_run.h):
// velocity Verlet, the dampers at the rate predicted at the step's end. Its
// order against closed forms (a damped linear oscillator; Hertz's impact,
// Johnson's peak force and contact duration) and, on each track, the order
// of P1 and of the whole force history against a run at an eighth of the step.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "sim/crossing_model.h"
#include "sim/hertz_law.h"
#include "sim/simulate_crossing.h"
#include "sim/vertical_mass.h"

namespace railjoint {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A mass on a spring and a damper, released from x0 at rest: the error at
// t = 5 periods against x(t) = exp(-zeta w t) (x0 cos(w_d t) + zeta w x0 / w_d
// sin(w_d t)). Second order: halving the step cuts it by 4 (3.5 asked). A
// damper taken at the half step's rate instead of the predicted one makes
// it first order (the old semi-implicit Euler's ratio: 2).
double oscillator_error(double zeta, int steps_per_period) {
  const double m = 2.0, w = 2.0 * kPi * 100.0, k = m * w * w, c = 2.0 * zeta * m * w, x0 = 1e-3;
  const double period = 2.0 * kPi / w, dt = period / steps_per_period;
  VerticalMass body(m, x0, 0.0);
  body.accelerate(-k * body.z_m - c * body.zdot_m_per_s, 0.0);
  for (int n = 0; n < 5 * steps_per_period; ++n) {
    body.advance(dt);
    body.accelerate(-k * body.z_m - c * body.zdot_m_per_s, 0.5 * dt);
  }
  const double t = 5.0 * period, wd = w * std::sqrt(1.0 - zeta * zeta);
  const double exact = std::exp(-zeta * w * t) * (x0 * std::cos(wd * t) + zeta * w * x0 / wd * std::sin(wd * t));
  return std::abs(body.z_m - exact) / x0;
}

TEST(ForceIntegration, ADampedOscillatorConvergesAtSecondOrder) {
  for (const double zeta : {0.0, 0.05, 0.3}) {
    const double coarse = oscillator_error(zeta, 50), fine = oscillator_error(zeta, 100), finer = oscillator_error(zeta, 200);
    std::printf("zeta %.2f: error at 50, 100, 200 steps a period %.3g, %.3g, %.3g (ratios %.2f, %.2f)\n", zeta, coarse,
                fine, finer, coarse / fine, fine / finer);
    EXPECT_GT(coarse / fine, 3.5);
    EXPECT_GT(fine / finer, 3.5);
  }
}

// Hertz's impact (Johnson, Contact Mechanics, 1985, sec. 11.4): a mass m
// meeting a rigid flat at V under F = (delta / G)^(3/2), no gravity, comes to
// rest at delta* = (5 m V^2 / (4 K))^(2/5), K = G^(-3/2) (its kinetic energy
// all in 2/5 K delta^(5/2)), with the peak force K delta*^(3/2), and leaves
// after T = (2 delta* / V) int_0^1 (1 - x^(5/2))^(-1/2) dx
// = (2 delta* / V) (2/5) B(2/5, 1/2) = 2.9433 delta* / V (Johnson's 2.94), at
// V (restitution 1). The thesis's wheel (750 kg, G of R = 0.475 m) at 1 m/s.
struct ImpactResult {
  double peak_N, duration_s, rebound_m_per_s;
};

ImpactResult hertz_impact(double dt) {
  const double m = 750.0, V = 1.0, G = default_hertz_constant_m_per_N2_3(0.475);
  VerticalMass wheel(m, 0.0, -V);  // z = -penetration
  wheel.accelerate(0.0, 0.0);
  std::vector<double> force{0.0};
  double t = 0.0, left_s = 0.0;
  while (true) {
    const double z_before = wheel.z_m;
    wheel.advance(dt);
    t += dt;
    const double f = wheel.z_m < 0.0 ? hertz_force_N(G, -wheel.z_m) : 0.0;
    wheel.accelerate(f, 0.5 * dt);
    force.push_back(f);
    if (wheel.z_m >= 0.0 && z_before < 0.0) {
      left_s = t - dt * wheel.z_m / (wheel.z_m - z_before);  // the gap's zero within the step
      break;
    }
  }
  // The peak between samples: the parabola's vertex through the largest and its neighbours.
  const std::size_t k = static_cast<std::size_t>(std::max_element(force.begin(), force.end()) - force.begin());
  const double a = force[k - 1], b = force[k], c = force[k + 1];
  return {b - 0.125 * (a - c) * (a - c) / (a - 2.0 * b + c), left_s, wheel.zdot_m_per_s};
}

TEST(ForceIntegration, AHertzImpactMatchesJohnsonsPeakForceAndDuration) {
  const double m = 750.0, V = 1.0, G = default_hertz_constant_m_per_N2_3(0.475), K = std::pow(G, -1.5);
  const double delta_m = std::pow(5.0 * m * V * V / (4.0 * K), 0.4);
  const double peak_N = K * std::pow(delta_m, 1.5);
  const double beta_function = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  const double duration_s = 2.0 * delta_m / V * 0.4 * beta_function;
  double previous_peak_error = 0.0;
  for (const int steps : {100, 200, 400}) {
    const ImpactResult r = hertz_impact(duration_s / steps);
    const double peak_error = std::abs(r.peak_N / peak_N - 1.0);
    std::printf("%d steps over the contact: peak %.6g N (Johnson %.6g N, %.2e), duration %.6g ms (%.6g ms, %.2e), "
                "rebound %.8f m/s\n",
                steps, r.peak_N, peak_N, peak_error, r.duration_s * 1e3, duration_s * 1e3,
                r.duration_s / duration_s - 1.0, r.rebound_m_per_s);
    // Verlet's error on an oscillation of frequency w is (w dt)^2 / 24 in its
    // phase; here w ~ pi / T: (pi / steps)^2 / 24, 4.1e-5 at 100 steps, 1e-5
    // at 200. Both asked within 4x that (the law is not linear).
    const double bound = 4.0 * std::pow(kPi / steps, 2) / 24.0;
    EXPECT_LT(peak_error, bound);
    EXPECT_LT(std::abs(r.duration_s / duration_s - 1.0), bound);
    EXPECT_NEAR(r.rebound_m_per_s, V, bound * V);  // restitution 1: Verlet loses no energy over the impact
    if (previous_peak_error > 0.0) {
      EXPECT_GT(previous_peak_error / peak_error, 3.0);
    }
    previous_peak_error = peak_error;
  }
}

// The whole force run on each track, every step at the one step (the
// pulse's finer steps off): P1 and the contact force history at
// 4e-6 and 2e-6 s against a run at 0.5e-6 s (whose own error, 1/16 of the
// 2e-6 s run's at second order, is left in). The history's error is the
// largest difference at the coarse run's sample times, over P1.
enum class Track { rigid, lumped, discrete };

struct RunForces {
  double p1_N;
  std::vector<double> force_N;
  double p2_N;
};

// `refine`: the impact's pulse at sim.refined_time_step (the default,
// pulse_window.h); without, every step at `step_s` (the scheme's own order).
// `restitution` below 1: Hunt and Crossley's damped contact (hertz_law.h).
RunForces force_run(Track track, bool sprung, double step_s, bool refine = false, double restitution = 1.0,
                    double refined_step_s = SimSettings{}.refined_time_step_s) {
  SimSettings s;
  s.refined_time_step_s = refine ? refined_step_s : step_s;
  ElasticCrossingSettings& e = s.make_inertial().contact.emplace<ElasticCrossingSettings>();
  e.contact.restitution = restitution;
  if (track == Track::lumped) e.track.emplace();
  if (track == Track::discrete) e.discrete_track.emplace();
  if (sprung) e.vehicle.emplace();
  s.make_inertial().force_time_step_s = step_s;
  JointParams joint;
  joint.theta_rad = kPi / 2;
  joint.beta_rad = 0.03;
  WheelParams wheel;
  wheel.lateral_m = 0.0;
  wheel.speed_m_per_s = 50.0;
  joint.length_m = std::max(1.0, rail_length_needed_m(joint, wheel, s));
  const SimulationResult r = simulate_crossing(joint, wheel, s);
  const ForceOutcome& f = *r.inertial()->forces;
  return {f.p1_N, f.contact_force_N, f.p2 ? f.p2->force_N : 0.0};
}

double history_error(const RunForces& coarse, const RunForces& reference, std::size_t stride) {
  double worst = 0.0;
  for (std::size_t k = 1; k < coarse.force_N.size() && k * stride < reference.force_N.size(); ++k) {
    worst = std::max(worst, std::abs(coarse.force_N[k] - reference.force_N[k * stride]));
  }
  return worst / reference.p1_N;
}

void expect_second_order(Track track, bool sprung, const char* name) {
  const RunForces coarse = force_run(track, sprung, 4e-6), fine = force_run(track, sprung, 2e-6),
                  reference = force_run(track, sprung, 0.5e-6);
  const double p1_coarse = std::abs(coarse.p1_N / reference.p1_N - 1.0);
  const double p1_fine = std::abs(fine.p1_N / reference.p1_N - 1.0);
  const double history_coarse = history_error(coarse, reference, 8), history_fine = history_error(fine, reference, 4);
  std::printf("%s: P1 %.1f N; P1 error at 4e-6 s %.2e, at 2e-6 s %.2e (ratio %.2f); history %.2e, %.2e (ratio %.2f)\n",
              name, reference.p1_N, p1_coarse, p1_fine, p1_coarse / p1_fine, history_coarse, history_fine,
              history_coarse / history_fine);
  EXPECT_GT(history_coarse / history_fine, 3.0);
  // P1 on the discrete track is within 2e-6 at 4e-6 s already, at the floor
  // its sampling leaves (the reference's own): its ratio says nothing there.
  if (p1_coarse > 1e-5) {
    EXPECT_GT(p1_coarse / p1_fine, 3.0);
  }
  EXPECT_LT(p1_coarse, 2e-4);
}

// With the pulse stepped at sim.refined_time_step (1e-6 s, pulse_window.h):
// P1 and P2 at the default 4e-6 s and at 2e-6 s against the run at 0.5e-6 s
// (which takes no finer steps: its step is below 1e-6 s). Both coarse runs
// step the pulse at 1e-6 s, so their P1 error is Verlet's there: (w dt)^2 / 24
// in the phase of the rail's ringing on the Hertz spring, w ~ 8.5e3 rad/s on
// the lumped track, 3e-6 (4.6e-6 measured at 1e-6 s everywhere); the bound is
// the 1e-5. Halving the step moves P1 and P2 by less than that too.
void expect_p1_within_1e5(Track track, bool sprung, const char* name) {
  const RunForces coarse = force_run(track, sprung, 4e-6, true), fine = force_run(track, sprung, 2e-6, true),
                  reference = force_run(track, sprung, 0.5e-6, true);
  std::printf("%s: P1 error at 4e-6 s %.2e, at 2e-6 s %.2e; P2 %.2e, %.2e\n", name, coarse.p1_N / reference.p1_N - 1,
              fine.p1_N / reference.p1_N - 1, reference.p2_N > 0 ? coarse.p2_N / reference.p2_N - 1 : 0.0,
              reference.p2_N > 0 ? fine.p2_N / reference.p2_N - 1 : 0.0);
  EXPECT_NEAR(coarse.p1_N / reference.p1_N, 1.0, 1e-5);
  EXPECT_NEAR(fine.p1_N / reference.p1_N, 1.0, 1e-5);
  EXPECT_NEAR(coarse.p1_N / fine.p1_N, 1.0, 1e-5);
  if (reference.p2_N > 0) {
    EXPECT_NEAR(coarse.p2_N / reference.p2_N, 1.0, 1e-5);
    EXPECT_NEAR(coarse.p2_N / fine.p2_N, 1.0, 1e-5);
  }
}

TEST(ForceIntegration, TheRigidTracksP1IsWithin1e5AtTheDefaultStep) { expect_p1_within_1e5(Track::rigid, false, "rigid"); }
TEST(ForceIntegration, TheLumpedTracksP1IsWithin1e5AtTheDefaultStep) {
  expect_p1_within_1e5(Track::lumped, false, "lumped");
}
TEST(ForceIntegration, TheDiscreteTracksP1IsWithin1e5AtTheDefaultStep) {
  expect_p1_within_1e5(Track::discrete, false, "discrete");
}

// A damped contact (restitution 0.2, the least the seeded crossings draw:
// alpha 4.92) closes on a spring up to 1 + alpha times Hertz's, so its
// pulse is stepped sqrt(1 + alpha) finer (elastic_crossing_run.cpp,
// damped_pulse_step_s). P1 at `sample_step_s` against a run sampled at
// 0.25e-6 s whose pulse is stepped at 0.1e-6 / 2.43 s (the rigid track, with
// no refined step: 0.25e-6 s split in 3; its own error, 1e-2 of the coarse
// run's or less, left in); the bound is the undamped runs'
// 1e-5 (above): measured 2.2e-6 and 2.5e-6, a quarter of it; the undamped
// runs' bound is kept since it is the target a user reads in forces.md.
// Second order: P1's error with the pulse's undamped step at
// `pulse_steps_s`, chosen so that the sub-steps the sample's step is split
// into (ceil(sample sqrt(1 + alpha) / step), sqrt(1 + alpha) = 2.43) halve
// exactly, falls as its square (3 asked for a halving, as for the whole run
// above). On an elastic track it is taken against a run sampled at the same
// instants with the pulse 8 times finer: the parabola's error through the
// samples (5.3e-7 at 1e-6 s), the same in both, cancels and the ratio reads
// the stepping alone.
void expect_damped_p1_within_1e5(Track track, const char* name, double sample_step_s,
                                 std::array<double, 2> pulse_steps_s) {
  const double e = 0.2;
  const bool rings = track != Track::rigid;
  const RunForces reference = force_run(track, false, 0.25e-6, true, e, 0.1e-6);
  // The rigid track steps its pulse at the run's own step (no refined step).
  const auto run_at = [&](double pulse_step_s) {
    return rings ? force_run(track, false, sample_step_s, true, e, pulse_step_s)
                 : force_run(track, false, pulse_step_s, true, e);
  };
  const RunForces standard = run_at(rings ? SimSettings{}.refined_time_step_s : sample_step_s);
  const RunForces coarse = run_at(pulse_steps_s[0]), fine = run_at(pulse_steps_s[1]);
  const RunForces same_samples = rings ? run_at(pulse_steps_s[1] / 8) : reference;
  const double p1_error = standard.p1_N / reference.p1_N - 1.0;
  const double coarse_error = std::abs(coarse.p1_N / same_samples.p1_N - 1.0);
  const double fine_error = std::abs(fine.p1_N / same_samples.p1_N - 1.0);
  const double halvings = 1.0;  // each pair of pulse steps halves the sub-step (above)
  std::printf("%s, restitution %.1f: P1 %.1f N; sampled at %.3g s: %.2e; the pulse's step %.3g, %.3g s: %.2e, %.2e "
              "(ratio %.2f)\n",
              name, e, reference.p1_N, sample_step_s, p1_error, pulse_steps_s[0], pulse_steps_s[1], coarse_error,
              fine_error, coarse_error / fine_error);
  EXPECT_LT(std::abs(p1_error), 1e-5);
  EXPECT_GT(coarse_error / fine_error, std::pow(3.0, halvings));
}

// The rigid track at the default step: before, -2.23e-5 (measured). Its
// pulse is the run's own step, split in 3 at 4e-6 and at 2e-6 s alike.
TEST(ForceIntegration, ADampedContactsP1OnTheRigidTrackIsWithin1e5AtTheDefaultStep) {
  expect_damped_p1_within_1e5(Track::rigid, "rigid", 4e-6, {4e-6, 2e-6});
}
// The lumped track sampled at 1e-6 s, where the parabola through the
// samples finds the crest of the converged history within 5.3e-7 (at the
// default 4e-6 s within 2.7e-5 on a damped crossing's sharper crest, a
// limit of the sampling the step does not touch: docs/not-done.md); its
// pulse at 1e-6 s before: -2.4e-5 (measured). The pulse's steps 1e-6 and
// 0.45e-6 s split each 1e-6 s sample in 3 and 6 (0.5e-6 s would split it
// in 5, a ratio of 5/3).
TEST(ForceIntegration, ADampedContactsP1OnTheLumpedTrackIsWithin1e5SampledAt1us) {
  expect_damped_p1_within_1e5(Track::lumped, "lumped", 1e-6, {1e-6, 0.45e-6});
}

TEST(ForceIntegration, TheRigidTrackConvergesAtSecondOrder) { expect_second_order(Track::rigid, false, "rigid"); }
TEST(ForceIntegration, TheLumpedTrackConvergesAtSecondOrder) { expect_second_order(Track::lumped, false, "lumped"); }
TEST(ForceIntegration, TheLumpedTrackUnderASprungMassConvergesAtSecondOrder) {
  expect_second_order(Track::lumped, true, "lumped, sprung");
}
TEST(ForceIntegration, TheDiscreteTrackConvergesAtSecondOrder) {
  expect_second_order(Track::discrete, false, "discrete");
}

}  // namespace
}  // namespace railjoint
