// Hunt and Crossley's damper taken implicitly over a step
// (sim/implicit_contact_damper.h): the solve against hand derivations. The
// force runs that needed it are tested where they run
// (elastic_crossing_test.cpp, timoshenko_rail_test.cpp).

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "sim/implicit_contact_damper.h"

namespace railjoint {
namespace {

// A mass m [kg] on a rigid floor under a contact of constant elastic force E
// and damping factor p: m du/dt = E (1 + p r), r = -u the closing rate, so
// u' = u - 1/p obeys m du'/dt = -c u', c = p E: a pure damper. Verlet's
// half kick with the last force, then the solve (W = dt / (2 m), the
// second half kick's rate per newton; P the last force), then the second
// half kick: by hand, u'_half = u'_n (1 - g/2) (the last force is -c u'_n),
// and u'_n+1 = u'_half - (g/2) u'_n+1, so u'_n+1 / u'_n = (1 - g/2) / (1 + g/2),
// g = c dt / m: the trapezoidal rule, stable at any g. The old step (the
// rate predicted with the last force, W = 0) iterates (u', a) by
// [[1 - g/2, (1 - g)/2], [-g, -g]], whose eigenvalues solve
// l^2 - (1 - 3g/2) l - g/2 = 0: -1 at g = 1, beyond 1 above it. g up to
// 1.9 here, where the force stays a push (beyond 2 the trapezoid
// overshoots to a pull, which the law clamps).
TEST(ImplicitContactDamper, APureDamperStepsAsTheTrapezoidalRule) {
  const double m_kg = 4.5, E_N = 1e5, dt_s = 4e-6;
  for (const double g : {0.1, 0.5, 1.0, 1.5, 1.9}) {
    const double c = g * m_kg / dt_s, p = c / E_N;
    const double u_prime = -1e-3;  // the force then pushes: -c u' > 0
    const double u = u_prime + 1.0 / p;
    const double last_N = -c * u_prime;  // the force at the step's start, in the mass's acceleration
    const double half_u = u + 0.5 * dt_s * last_N / m_kg;
    const double predicted_u = half_u + 0.5 * dt_s * last_N / m_kg;
    DampedContact contact{E_N, p, -predicted_u, 1.0, last_N};
    const double W = 0.5 * dt_s / m_kg;
    const DampedContactForces f = solve_damped_contacts({contact, DampedContact{}}, {true, false}, {{{W, 0.0}, {0.0, 0.0}}});
    const double next_u = half_u + 0.5 * dt_s * f.force_N[0] / m_kg;
    const double ratio = (next_u - 1.0 / p) / u_prime, trapezoid = (1.0 - 0.5 * g) / (1.0 + 0.5 * g);
    std::printf("g %.2f: u'_n+1 / u'_n %.12f, trapezoid %.12f; closing rate %.6e m/s (-u %.6e)\n", g, ratio,
                trapezoid, f.closing_m_per_s[0], -next_u);
    // u' is 1e-3 of 1/p's scale or less: the ratio carries the cancellation
    // u - 1/p, some 1e-16 / 1e-3 x |u| p: 1e-9 allowed, measured below 1e-11.
    EXPECT_NEAR(ratio, trapezoid, 1e-9);
    // The rate it reports is the one the kick leaves (the balance's damping power takes it).
    EXPECT_NEAR(f.closing_m_per_s[0], -next_u, 1e-12 * std::abs(next_u) + 1e-15);
  }
}

// Two contacts on one wheel alike in everything: by symmetry F0 = F1 = F,
// F = E (1 + p (r + n (W00 + W01) (P - n F))), so by hand
// F = E (1 + p (r + n (W00 + W01) P)) / (1 + E p n^2 (W00 + W01)).
TEST(ImplicitContactDamper, TwoAlikeContactsShareTheClosedForm) {
  const double E = 2e5, p = 3.0, r = 0.2, n = 0.99, P = 1.5e5, W00 = 2e-6, W01 = 7e-7;
  const DampedContact c{E, p, r, n, P};
  const DampedContactForces f = solve_damped_contacts({c, c}, {true, true}, {{{W00, W01}, {W01, W00}}});
  const double by_hand = E * (1.0 + p * (r + n * (W00 + W01) * P)) / (1.0 + E * p * n * n * (W00 + W01));
  std::printf("F0 %.9f N, F1 %.9f N, by hand %.9f N\n", f.force_N[0], f.force_N[1], by_hand);
  // A 2 x 2 Cramer solve against one division: a few ulp of 3e5 N.
  EXPECT_NEAR(f.force_N[0], by_hand, 1e-9 * by_hand);
  EXPECT_NEAR(f.force_N[1], by_hand, 1e-9 * by_hand);
}

// Unlike contacts: the law holds at the solution (each force is E (1 + p r)
// at the rate its solve reports, r = r_pred + n sum_j W_kj (P_j - n_j F_j)),
// an invariant checked from the inputs; and an undamped contact (p 0) keeps
// its elastic force exactly.
TEST(ImplicitContactDamper, TheLawHoldsAtTheSolution) {
  const DampedContact a{3e5, 8.0, 0.05, 0.98, 2e5}, b{1e5, 0.0, -0.3, 1.0, 1.2e5};
  const std::array<std::array<double, 2>, 2> W{{{3e-6, 1e-6}, {1e-6, 2.5e-6}}};
  const DampedContactForces f = solve_damped_contacts({a, b}, {true, true}, W);
  const DampedContact in[2] = {a, b};
  for (std::size_t k = 0; k < 2; ++k) {
    double r = in[k].closing_m_per_s;
    for (std::size_t j = 0; j < 2; ++j) r += in[k].normal_z * W[k][j] * (in[j].last_pressed_N - in[j].normal_z * f.force_N[j]);
    const double law = in[k].elastic_N * (1.0 + in[k].per_rate_s_per_m * r);
    std::printf("contact %zu: F %.6f N, law at its rate %.6f N, rate %.9f (reported %.9f) m/s\n", k, f.force_N[k], law,
                r, f.closing_m_per_s[k]);
    EXPECT_NEAR(f.force_N[k], law, 1e-9 * in[k].elastic_N);
    EXPECT_NEAR(f.closing_m_per_s[k], r, 1e-12);
  }
  EXPECT_EQ(f.force_N[1], b.elastic_N);
}

// A contact whose law asks for a pull at the solution bears nothing, and
// the other is then solved alone: by hand (F0 = 0)
// F1 = E1 (1 + p1 (r1 + n1 (W10 P0 + W11 P1))) / (1 + E1 p1 n1^2 W11).
TEST(ImplicitContactDamper, AContactThatWouldPullBearsNothing) {
  const DampedContact parting{1e4, 50.0, -0.5, 1.0, 0.0}, bearing{2e5, 2.0, 0.1, 1.0, 1.9e5};
  const std::array<std::array<double, 2>, 2> W{{{4e-6, 1e-6}, {1e-6, 4e-6}}};
  const DampedContactForces f = solve_damped_contacts({parting, bearing}, {true, true}, W);
  const double by_hand = 2e5 * (1.0 + 2.0 * (0.1 + 4e-6 * 1.9e5)) / (1.0 + 2e5 * 2.0 * 4e-6);
  std::printf("parting %.6f N, bearing %.6f N (by hand %.6f N)\n", f.force_N[0], f.force_N[1], by_hand);
  EXPECT_EQ(f.force_N[0], 0.0);
  EXPECT_NEAR(f.force_N[1], by_hand, 1e-9 * by_hand);
  // The parting one's law at the rate the other's force leaves it: still a pull.
  EXPECT_LT(1.0 + 50.0 * (-0.5 + 1e-6 * (1.9e5 - f.force_N[1])), 0.0);
}

}  // namespace
}  // namespace railjoint
