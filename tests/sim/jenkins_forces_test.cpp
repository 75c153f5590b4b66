// Jenkins et al.'s P1 and P2 (sim/impact_force_estimate.h): the published
// worked case, the calculator's variant of P2 kept apart from ours, and the
// limits any form of the two formulas must meet (a rigid track, no damping,
// linearity in the speed, a wheel at rest).

#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "sim/impact_force_estimate.h"

namespace railjoint {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The worked case (SI): static load, total dip angle 2 alpha, speed, the
// linearised Hertz stiffness, the rail mass taking part in P1, the unsprung
// mass, the track mass, stiffness and damping taking part in P2.
constexpr double kP0_N = 100e3;
constexpr double kDip_rad = 0.02;  // 2 alpha
constexpr double kSpeed_m_per_s = 30.0;
constexpr double kHertz_N_per_m = 1.4e9;   // K_H
constexpr double kTrackMassP1_kg = 500.0;  // m_T1
constexpr double kUnsprung_kg = 350.0;     // m_u
constexpr double kTrackMassP2_kg = 800.0;  // m_T
constexpr double kTrack_N_per_m = 4e7;     // K_T
constexpr double kTrack_N_s_per_m = 2e4;   // C_T

// By hand: reduced mass m_T1 m_u / (m_T1 + m_u) = 175000 / 850 = 205.882 kg;
// sqrt(1.4e9 x 205.882) = 536,875.5 N s/m; x 2 alpha V = 0.6 gives
// 322,125.3 N over P0: P1 = 422,125.3 N.
TEST(JenkinsForces, P1OfThePublishedWorkedCase) {
  const double p1 =
      jenkins_p1_force_N(kP0_N, kDip_rad, kSpeed_m_per_s, kHertz_N_per_m, kUnsprung_kg, kTrackMassP1_kg);
  std::printf("P1 = %.4f N (published 422,125.3 N)\n", p1);
  // The published value has 1 decimal: its rounding is 0.05 N.
  EXPECT_NEAR(p1, 422125.3, 0.05);
}

// The standard form, by hand: m_u + m_T = 1150 kg; sqrt(K_T (m_u + m_T)) =
// sqrt(4.6e10) = 214,476.2; the bracket 1 - 2e4 pi / (4 x 214,476.2) =
// 1 - 0.073239 = 0.926761; sqrt(m_u / (m_u + m_T)) = 0.551677; sqrt(K_T m_u)
// = sqrt(1.4e10) = 118,321.6; 0.6 x 0.551677 x 0.926761 x 118,321.6 =
// 36,296.8 N over P0: P2 = 136,296.8 N.
//
// The public calculator writes the bracket as 1 - C_T pi / sqrt(K_T m_T):
// sqrt(3.2e10) = 178,885.4, 1 - 0.351241 = 0.648759, P2 = 125,408.8 N.
// We use the standard form. The bracket is the first-order loss to the
// damping over the quarter period in which the mass m_u + m_T on K_T, C_T
// reaches its peak: damping ratio zeta = C_T / (2 sqrt(K_T (m_u + m_T))),
// amplitude decay over a quarter period zeta pi / 2 = C_T pi / (4 sqrt(K_T
// (m_u + m_T))). The calculator's bracket has neither the quarter period
// (4x larger a loss) nor the vibrating mass (m_T alone).
TEST(JenkinsForces, P2OfThePublishedWorkedCaseIsTheStandardFormNotTheCalculators) {
  const double p2 = jenkins_p2_force_N(kP0_N, kDip_rad, kSpeed_m_per_s, kUnsprung_kg, kTrackMassP2_kg,
                                       kTrack_N_per_m, kTrack_N_s_per_m);
  // The calculator's own expression, written out here.
  const double calculator_p2 =
      kP0_N + kDip_rad * kSpeed_m_per_s * std::sqrt(kUnsprung_kg / (kUnsprung_kg + kTrackMassP2_kg)) *
                  (1.0 - kTrack_N_s_per_m * kPi / std::sqrt(kTrack_N_per_m * kTrackMassP2_kg)) *
                  std::sqrt(kTrack_N_per_m * kUnsprung_kg);
  std::printf("P2 = %.4f N (standard form, published 136,296.8 N); calculator's form %.4f N (125,408.8 N)\n", p2,
              calculator_p2);
  // Both published values have 1 decimal: their rounding is 0.05 N.
  EXPECT_NEAR(p2, 136296.8, 0.05);
  EXPECT_NEAR(calculator_p2, 125408.8, 0.05);
  // The two forms are 10.9 kN apart: ours is not the calculator's.
  EXPECT_GT(std::abs(p2 - calculator_p2), 1e3);
}

// An immovable track: the reduced mass is m_u, and P1 = P0 + 2 alpha V
// sqrt(K_H m_u) = 1e5 + 0.6 sqrt(1.4e9 x 350) = 1e5 + 0.6 x 700,000 = 520,000 N.
TEST(JenkinsForces, P1OnAnInfinitelyHeavyTrackIsTheRigidTrackValue) {
  const double inf = std::numeric_limits<double>::infinity();
  const double p1 = jenkins_p1_force_N(kP0_N, kDip_rad, kSpeed_m_per_s, kHertz_N_per_m, kUnsprung_kg, inf);
  const double expected = kP0_N + kDip_rad * kSpeed_m_per_s * std::sqrt(kHertz_N_per_m * kUnsprung_kg);
  std::printf("P1 rigid track = %.6f N (by hand 520,000 N)\n", p1);
  // Both are a handful of correctly rounded operations on ~5e5: 1e-9 relative is ~1e6 ulp of room.
  EXPECT_NEAR(p1, expected, 1e-9 * expected);
  EXPECT_NEAR(p1, 520000.0, 1e-9 * 520000.0);
  // A finite but huge track mass tends to it: 1e12 kg lowers the reduced mass
  // by m_u / m_T1 = 3.5e-10, P1 - P0 by half that, 1.75e-10 x 420 kN = 7.4e-5 N.
  const double p1_heavy = jenkins_p1_force_N(kP0_N, kDip_rad, kSpeed_m_per_s, kHertz_N_per_m, kUnsprung_kg, 1e12);
  std::printf("P1 with a 1e12 kg track = %.6f N, %.3g N below\n", p1_heavy, p1 - p1_heavy);
  // 7.4e-5 N by hand; 1e-3 N is ~10x above.
  EXPECT_NEAR(p1_heavy, p1, 1e-3);
  EXPECT_LE(p1_heavy, p1);
}

// No damping: the bracket is 1 and P2 = P0 + 2 alpha V m_u sqrt(K_T / (m_u + m_T))
// = 1e5 + 0.6 x 350 x sqrt(4e7 / 1150) = 1e5 + 210 x 186.50096 = 139,165.20 N.
TEST(JenkinsForces, P2WithoutDampingIsTheUndampedQuarterPeriodPeak) {
  const double p2 = jenkins_p2_force_N(kP0_N, kDip_rad, kSpeed_m_per_s, kUnsprung_kg, kTrackMassP2_kg,
                                       kTrack_N_per_m, 0.0);
  const double expected = kP0_N + kDip_rad * kSpeed_m_per_s * kUnsprung_kg *
                                      std::sqrt(kTrack_N_per_m / (kUnsprung_kg + kTrackMassP2_kg));
  std::printf("P2 undamped = %.4f N (by hand 139,165.20 N), expected %.4f N\n", p2, expected);
  // The same product taken in another order: round-off of a few ulp; 1e-12 relative is ~1e4 ulp.
  EXPECT_NEAR(p2, expected, 1e-12 * expected);
  // The hand value has 2 decimals: its rounding is 0.005 N.
  EXPECT_NEAR(p2, 139165.20, 0.005);
}

// Both peaks rise over P0 in proportion to the speed (the closing speed 2 alpha V).
TEST(JenkinsForces, PeaksOverTheStaticLoadAreLinearInSpeedAndZeroAtRest) {
  const auto p1 = [](double v) {
    return jenkins_p1_force_N(kP0_N, kDip_rad, v, kHertz_N_per_m, kUnsprung_kg, kTrackMassP1_kg);
  };
  const auto p2 = [](double v) {
    return jenkins_p2_force_N(kP0_N, kDip_rad, v, kUnsprung_kg, kTrackMassP2_kg, kTrack_N_per_m, kTrack_N_s_per_m);
  };
  const double p1_ratio = (p1(2.0 * kSpeed_m_per_s) - kP0_N) / (p1(kSpeed_m_per_s) - kP0_N);
  const double p2_ratio = (p2(2.0 * kSpeed_m_per_s) - kP0_N) / (p2(kSpeed_m_per_s) - kP0_N);
  std::printf("(P - P0) at 60 m/s over 30 m/s: P1 %.15f, P2 %.15f; at rest P1 %.3f N, P2 %.3f N\n", p1_ratio,
              p2_ratio, p1(0.0), p2(0.0));
  // Doubling a factor is exact in binary; subtracting P0 back costs a few ulp of ~4e5 N: 1e-12 is ample.
  EXPECT_NEAR(p1_ratio, 2.0, 1e-12);
  EXPECT_NEAR(p2_ratio, 2.0, 1e-12);
  // A wheel at rest adds nothing: exactly P0.
  EXPECT_EQ(p1(0.0), kP0_N);
  EXPECT_EQ(p2(0.0), kP0_N);
}

// The calculator's bracket as railjoint gives it beside the default
// (jenkins_p2_calculator_form_N): the calculator's own worked number,
// 125,408.8 N, written out above from its expression; and with no damping
// both brackets are 1, so both forms are the undamped peak.
TEST(JenkinsForces, TheCalculatorsFormGivesItsWorkedNumberAndMeetsTheStandardFormUndamped) {
  const double calculator = jenkins_p2_calculator_form_N(kP0_N, kDip_rad, kSpeed_m_per_s, kUnsprung_kg, kTrackMassP2_kg,
                                                         kTrack_N_per_m, kTrack_N_s_per_m);
  std::printf("calculator's form %.4f N (125,408.8 N)\n", calculator);
  EXPECT_NEAR(calculator, 125408.8, 0.05);
  const double undamped_standard =
      jenkins_p2_force_N(kP0_N, kDip_rad, kSpeed_m_per_s, kUnsprung_kg, kTrackMassP2_kg, kTrack_N_per_m, 0.0);
  const double undamped_calculator =
      jenkins_p2_calculator_form_N(kP0_N, kDip_rad, kSpeed_m_per_s, kUnsprung_kg, kTrackMassP2_kg, kTrack_N_per_m, 0.0);
  EXPECT_EQ(undamped_standard, undamped_calculator);
}

}  // namespace
}  // namespace railjoint
