// The coupled spanning contact (sim/rail_end_patch_share.h) across an
// end-post gap, against the boundary-element solution of the wheel on two
// rail ends that the gap separates (rail_end_share_gap_reference.h).
//
// What is compared: each rail end's force at the solver's approach. The
// solver takes the load W and gives the approach delta and each rail end's
// carried load; the model takes each rail end's penetration at that approach
// (delta less its touching point's gap over the lowest) and gives its force
// (share x Hertz at the effective penetration), as the force run does. The
// differences are over W: (F_i,model - F_i,solver) / W for each rail end,
// sum F_i,model / W - 1 for the total, as the closed-gap check
// (rail_end_patch_share_test.cpp) reports it.
//
// What each side assumes. The model: each rail end a Hertz contact at its
// touching point (the wheel's and the crown's curvatures, its patch whole
// even at the cut's edge), the two patches at the same y, coupled through
// 2 E* (the wheel's surface alone) across a gap. The solver: the same
// bodies as half-spaces, either the rail ends apart (each its own
// half-space, the wheel over both: what 2 E* stands for) or one half-space
// continuous across the gap (E*: the rail's surface pressed too). Both are
// approximations: a rail end is a quarter-space with a free end face, more
// compliant near it than either.
//
// Measured (RailEndShareGapStudy, label study; docs/forces.md has the
// table): where both Hertz patches clear the gap the model is within
// 0.14 % of W (the sum of two springs 2.5-8.6 % over); where the gap cuts a
// patch it is 3 % under to 66 % over, most with the wheel over a wide gap:
// the model takes each patch whole about its touching point. The force run
// takes the empirical Hertz constant at a cut's edge, not the ellipse's
// taken here; that law is not under test.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "models/half_space_influence.h"
#include "models/hertz_contact.h"
#include "models/hertz_ellipse.h"
#include "models/normal_contact_solver.h"
#include "sim/rail_end_patch_share.h"
#include "tests/sim/rail_end_share_gap_reference.h"

namespace railjoint {
namespace {

using gap_reference::Bodies;
using gap_reference::GapJoint;
using gap_reference::GapSolution;
using gap_reference::kRx;
using gap_reference::kRy;

constexpr double kPi = 3.14159265358979323846;

double steel_e_star_Pa() {
  const HertzMaterial steel;  // E 210 GPa, nu 0.3
  return combined_modulus_Pa(steel.youngs_modulus_Pa, steel.poisson_ratio, steel.youngs_modulus_Pa,
                             steel.poisson_ratio);
}

EllipticalHertz wheel_on_crown() { return *elliptical_hertz({0.5 / kRx, 0.5 / kRy}, HertzMaterial{}); }

struct ModelForces {
  std::array<double, 2> force_N{};
  std::array<gap_reference::TouchingPoint, 2> touching;
  double apart = 0.0;  ///< the touching points' distance along x over the larger patch's semi-length
  std::array<bool, 2> patch_clear{};  ///< Hertz's ellipse at the touching point lies on its own rail end
  double uncoupled_N = 0.0;  ///< the sum of the two Hertz springs at the same penetrations (no coupling)
};

/// Whether Hertz's ellipse (semi-axes along x and y) about rail end i's
/// touching point lies on rail end i: 64 points of its edge.
bool patch_on_own_rail_end(const GapJoint& j, int rail, const gap_reference::TouchingPoint& p, const HertzPatch& patch) {
  for (int k = 0; k < 64; ++k) {
    const double phi = 2 * kPi * k / 64;
    if (gap_reference::rail_at(j, p.x_m + patch.semi_axis_x_m * std::cos(phi), p.y_m + patch.semi_axis_y_m * std::sin(phi)) !=
        rail) {
      return false;
    }
  }
  return true;
}

/// The force run's coupled contact at the approach delta: each rail end's
/// penetration delta - (h_i - h_min), its patch Hertz's at its touching
/// point, coupled through `coupling_modulus_Pa`.
ModelForces coupled_model(const GapJoint& j, double approach_m, double coupling_modulus_Pa) {
  const EllipticalHertz hertz = wheel_on_crown();
  const double G = hertz.hertz_constant_m_per_N2_3;
  ModelForces out;
  out.touching = {gap_reference::touching_point(j, 0), gap_reference::touching_point(j, 1)};
  const double h_min_m = std::min(out.touching[0].gap_m, out.touching[1].gap_m);
  const auto patch_at = [&](int i, double penetration_m) -> RailEndPatch {
    const double x_m = out.touching[static_cast<std::size_t>(i)].x_m;
    if (!(penetration_m > 0.0)) return {x_m, 0.0, 0.0};
    const double force_N = std::pow(penetration_m / G, 1.5);
    return {x_m, hertz_patch(hertz, force_N).semi_axis_x_m, force_N};
  };
  const std::array<double, 2> penetration_m{approach_m - (out.touching[0].gap_m - h_min_m),
                                            approach_m - (out.touching[1].gap_m - h_min_m)};
  const SpanningContact spanning = spanning_contact(penetration_m, patch_at, coupling_modulus_Pa);
  out.uncoupled_N = patch_at(0, penetration_m[0]).force_N + patch_at(1, penetration_m[1]).force_N;
  for (int i = 0; i < 2; ++i) {
    out.force_N[static_cast<std::size_t>(i)] =
        spanning.share[static_cast<std::size_t>(i)] *
        patch_at(i, spanning.effective_penetration_m[static_cast<std::size_t>(i)]).force_N;
  }
  for (int i = 0; i < 2; ++i) {
    const double force_N = patch_at(i, penetration_m[static_cast<std::size_t>(i)]).force_N;
    out.patch_clear[static_cast<std::size_t>(i)] =
        force_N == 0.0 || patch_on_own_rail_end(j, i, out.touching[static_cast<std::size_t>(i)], hertz_patch(hertz, force_N));
  }
  const double semi_m = std::max(patch_at(0, penetration_m[0]).semi_length_m, patch_at(1, penetration_m[1]).semi_length_m);
  out.apart = semi_m > 0.0 ? std::abs(out.touching[0].x_m - out.touching[1].x_m) / semi_m : 0.0;
  return out;
}

struct Comparison {
  std::array<double, 2> end_error{};  ///< (F_i,model - F_i,solver) / W
  double total_error = 0.0;           ///< sum F_i,model / W - 1
  double uncoupled_error = 0.0;       ///< the sum of two springs / W - 1: what the coupling corrects
  double lesser_share = 0.0;          ///< the solver's lesser rail-end load / W
  double apart = 0.0;
  int edges = 0;  ///< touching points at a cut's edge (0, 1, 2)
  bool clear = false;  ///< both patches clear of the gap: each rail end's own law is Hertz's
};

Comparison compare(const GapJoint& j, double load_N, const GapSolution& s, double coupling_modulus_Pa) {
  const ModelForces m = coupled_model(j, s.approach_m, coupling_modulus_Pa);
  Comparison c;
  for (int i = 0; i < 2; ++i) {
    c.end_error[static_cast<std::size_t>(i)] = (m.force_N[static_cast<std::size_t>(i)] - s.force_N[static_cast<std::size_t>(i)]) / load_N;
  }
  c.total_error = (m.force_N[0] + m.force_N[1]) / load_N - 1.0;
  c.lesser_share = std::min(s.force_N[0], s.force_N[1]) / load_N;
  c.uncoupled_error = m.uncoupled_N / load_N - 1.0;
  c.apart = m.apart;
  c.edges = static_cast<int>(m.touching[0].on_cut_edge) + static_cast<int>(m.touching[1].on_cut_edge);
  c.clear = m.patch_clear[0] && m.patch_clear[1];
  return c;
}

double deg(double rad) { return rad * 180.0 / kPi; }
double rad(double deg_value) { return deg_value * kPi / 180.0; }

// ---------------------------------------------------------------- the solver

TEST(RailEndShareGap, ReferenceSolverIsTheModelsSolverOnOneHalfSpace) {
  // With one operator (one half-space) the conjugate gradient written in the
  // reference is the models/ solver's problem with no_surface on the gap:
  // the same approach and loads to the solvers' tolerances.
  const GapJoint j{0.006, rad(45), 0.004, 0.002};
  const double load_N = 120e3, cell_m = 0.5e-3, e_star = steel_e_star_Pa();
  const GapSolution mine = gap_reference::solve_gap_contact(j, load_N, cell_m, Bodies::kOneHalfSpace, e_star);
  ASSERT_TRUE(mine.converged);
  const double h_min_m = gap_reference::lowest_gap_m(j);
  // The same box as the reference's first try (its pressure did not reach
  // the border there, or the sizes below differ).
  const auto grid = gap_reference::gap_grid(j, h_min_m, gap_reference::first_reach_m(load_N), cell_m);
  ASSERT_EQ(grid.box.nx, mine.cells_x);
  ASSERT_EQ(grid.box.ny, mine.cells_y);
  NormalContactProblem problem;
  problem.gap_m = grid.gap_m;
  problem.no_surface = !grid.bears;
  problem.normal_force_N = load_N;
  const HalfSpaceConvolution convolution(grid.box.nx, grid.box.ny, cell_m, cell_m, e_star);
  const NormalContactSolution theirs = solve_normal_contact(problem, convolution);
  ASSERT_TRUE(theirs.converged);
  const double theirs_0_N = grid.on_0.select(theirs.pressure_Pa, 0.0).sum() * cell_m * cell_m;
  std::printf("approach %.9e vs %.9e m; rail 0 %.3f vs %.3f kN of %.0f\n", mine.approach_m, theirs.approach_m,
              1e-3 * mine.force_N[0], 1e-3 * theirs_0_N, 1e-3 * load_N);
  EXPECT_NEAR(mine.approach_m, theirs.approach_m, 1e-6 * theirs.approach_m);
  EXPECT_NEAR(mine.force_N[0], theirs_0_N, 1e-6 * load_N);
  EXPECT_GT(std::min(mine.force_N[0], mine.force_N[1]), 0.1 * load_N);  // both bear: the case tests the split
}

TEST(RailEndShareGap, OneRailEndAloneIsHertzEitherWay) {
  // The wheel 20 mm onto rail end 1, the other's edge 23 mm off (its gap
  // 0.56 mm against an approach of 0.1 mm): one Hertz contact, whatever the
  // bodies across the gap. Hertz to the 0.5 mm cells' 2e-3 (the closed-gap
  // test's bound at 0.4 mm).
  const GapJoint j{0.006, rad(90), 0.0, 0.020};
  const double load_N = 150e3, G = wheel_on_crown().hertz_constant_m_per_N2_3;
  for (const Bodies bodies : {Bodies::kOneHalfSpace, Bodies::kRailEndsApart}) {
    const GapSolution s = gap_reference::solve_gap_contact(j, load_N, 0.5e-3, bodies, steel_e_star_Pa());
    ASSERT_TRUE(s.converged);
    const double hertz_approach_m = G * std::pow(load_N, 2.0 / 3.0);
    std::printf("approach %.6e m, Hertz %.6e m; rail 0 carries %.3e N\n", s.approach_m, hertz_approach_m, s.force_N[0]);
    EXPECT_EQ(s.force_N[0], 0.0);
    EXPECT_NEAR(s.approach_m / hertz_approach_m, 1.0, 2e-3);
  }
}

TEST(RailEndShareGap, SquareGapUnderTheWheelsLowestPointSplitsTheLoadInHalf) {
  // Symmetric about the gap's centre: each rail end carries W / 2 in the
  // solver (to the iteration's tolerance) and in the model (exactly).
  const GapJoint j{0.006, rad(90), 0.0, 0.0};
  const double load_N = 150e3;
  for (const Bodies bodies : {Bodies::kOneHalfSpace, Bodies::kRailEndsApart}) {
    const GapSolution s = gap_reference::solve_gap_contact(j, load_N, 0.5e-3, bodies, steel_e_star_Pa());
    ASSERT_TRUE(s.converged);
    EXPECT_NEAR(s.force_N[0] / load_N, 0.5, 1e-6);
    EXPECT_NEAR(s.force_N[1] / load_N, 0.5, 1e-6);
    const ModelForces m = coupled_model(j, s.approach_m, 2 * steel_e_star_Pa());
    EXPECT_NEAR(m.force_N[0], m.force_N[1], 1e-9 * load_N);
  }
}

TEST(RailEndShareGap, RailEndsApartAreStifferThanOneHalfSpace) {
  // Each rail end its own body takes the rail's surface out of the
  // coupling: u = K p / 2 + sum_i m_i K (m_i p) / 2 <= K p for p >= 0 (K's
  // coefficients are positive), so under the same load the approach is at
  // most one half-space's, and less where both bear.
  const GapJoint j{0.002, rad(90), 0.0, 0.0005};
  const double load_N = 150e3;
  const GapSolution one = gap_reference::solve_gap_contact(j, load_N, 0.5e-3, Bodies::kOneHalfSpace, steel_e_star_Pa());
  const GapSolution apart = gap_reference::solve_gap_contact(j, load_N, 0.5e-3, Bodies::kRailEndsApart, steel_e_star_Pa());
  std::printf("approach: one half-space %.6e m, rail ends apart %.6e m\n", one.approach_m, apart.approach_m);
  EXPECT_LT(apart.approach_m, one.approach_m);
}

// ------------------------------------------------------- the coupled model

struct Sample {
  GapJoint joint;
  double load_N = 150e3;
};

std::string describe(const Sample& c) {
  char text[128];
  std::snprintf(text, sizeof text, "gap %4.1f mm  %2.0f deg  beta %.4f  x_w %+6.2f mm  W %3.0f kN", 1e3 * c.joint.gap_m,
                deg(c.joint.cut_angle_rad), c.joint.dip_rad, 1e3 * c.joint.wheel_x_m, 1e-3 * c.load_N);
  return text;
}

struct Row {
  Sample sample;
  Comparison apart, one;  ///< the model (2 E*) against the rail ends apart; the model (E*) against one half-space
  double closed_gap_modulus_error = 0.0;  ///< the model with the closed gap's E* against the rail ends apart: total
};

Row evaluate(const Sample& c, double cell_m) {
  const double e_star = steel_e_star_Pa();
  const GapSolution apart = gap_reference::solve_gap_contact(c.joint, c.load_N, cell_m, Bodies::kRailEndsApart, e_star);
  const GapSolution one = gap_reference::solve_gap_contact(c.joint, c.load_N, cell_m, Bodies::kOneHalfSpace, e_star);
  EXPECT_TRUE(apart.converged && one.converged) << describe(c);
  return {c, compare(c.joint, c.load_N, apart, 2 * e_star), compare(c.joint, c.load_N, one, e_star),
          compare(c.joint, c.load_N, apart, e_star).total_error};
}

void print_row(const Row& r) {
  std::printf(
      "%s  lesser %.3f  apart %5.2f  edges %d clear %d | 2E* vs apart: %+7.4f %+7.4f total %+7.4f (two springs %+7.4f) | "
      "E* vs one: total %+7.4f | E* vs apart: total %+7.4f\n",
      describe(r.sample).c_str(), r.apart.lesser_share, r.apart.apart, r.apart.edges, static_cast<int>(r.apart.clear),
      r.apart.end_error[0], r.apart.end_error[1], r.apart.total_error, r.apart.uncoupled_error, r.one.total_error,
      r.closed_gap_modulus_error);
}

TEST(RailEndShareGap, CoupledModelWithinOnePercentWherePatchesClearTheGap) {
  // Dips large enough that each rail end's Hertz patch lies on its own
  // surface (R beta > g / 2 + a on a square cut): each rail end's own law is Hertz's and
  // what couples them is the far field, through the wheel alone (2 E*) with
  // the rail ends apart, through both surfaces (E*) on one half-space. The
  // force run's vouched 1 % (the closed gap's, kSpanningContactVouchedApart)
  // holds: measured within 0.14 % of W on 23 random cases of two seeds
  // (RailEndShareGapStudy), 0.06 % here, where the sum of two springs is
  // 2.7-7.3 % over; the grid moves it by 0.03 %.
  const double load_N = 150e3;
  for (const double gap_m : {0.002, 0.006, 0.010}) {
    for (const double angle_deg : {90.0, 45.0, 30.0}) {
      // 0.027-0.035 rad on a square cut, 0.02 more at 30 deg, where the
      // cut crosses the patch's width b at b cot(theta) along the track.
      const double dip_rad = 0.025 + gap_m + 0.02 * (90.0 - angle_deg) / 60.0;
      const double wheel_x_m = angle_deg == 90.0 ? 0.0 : (angle_deg == 45.0 ? 0.0005 : 0.0007);  // shares 1/2 to ~1/10
      const Sample c{{gap_m, rad(angle_deg), dip_rad, wheel_x_m}, load_N};
      const Row r = evaluate(c, 0.5e-3);
      print_row(r);
      ASSERT_TRUE(r.apart.clear) << describe(c);
      EXPECT_GT(r.apart.lesser_share, 0.05) << describe(c);  // both bear
      // The body assumption matters: the closed gap's E* (the rail's surface
      // pressed too) against the rail ends apart misses by 2.5-6 %.
      EXPECT_LT(r.closed_gap_modulus_error, -0.02) << describe(c);
      for (const Comparison& k : {r.apart, r.one}) {
        EXPECT_LT(std::abs(k.end_error[0]), 1e-2) << describe(c);
        EXPECT_LT(std::abs(k.end_error[1]), 1e-2) << describe(c);
        EXPECT_LT(std::abs(k.total_error), 1e-2) << describe(c);
      }
    }
  }
}

TEST(RailEndShareGap, CoupledModelOverstatesWhereAPatchIsCutByTheGap) {
  // The disagreement docs/forces.md reports (not a bound the model meets):
  // the wheel over a square 10 mm gap touches both rail ends at their
  // edges; the model takes each Hertz patch whole about its edge, the
  // solver's rail ends carry only on their surfaces. Measured +57.7 % of W
  // (rail ends apart) and +50.8 % (one half-space, E*); over 40 % in both
  // while the model is as it is (a fix turns this test round).
  const Sample c{{0.010, rad(90), 0.0, 0.0}, 150e3};
  const Row r = evaluate(c, 0.5e-3);
  print_row(r);
  EXPECT_GT(r.apart.total_error, 0.4);
  EXPECT_GT(r.one.total_error, 0.4);
}

// ------------------------------------------------------------ the study

/// Rail end i's own force-penetration law by the solver (the other rail end
/// absent), tabulated at loads from 3 % to 130 % of W and interpolated in
/// log-log (Hertz's 3/2 power outside): its patch cut by the gap, as Hertz's
/// is not.
struct AloneLaw {
  std::vector<double> log_penetration, log_force, centroid_x_m;
  /// Where the load acts at this force: the table's nearest entry.
  double centroid_at_m(double force_N) const {
    std::size_t best = 0;
    for (std::size_t k = 1; k < log_force.size(); ++k) {
      if (std::abs(log_force[k] - std::log(force_N)) < std::abs(log_force[best] - std::log(force_N))) best = k;
    }
    return centroid_x_m[best];
  }
  double force_N(double penetration_m) const {
    if (!(penetration_m > 0.0)) return 0.0;
    const double x = std::log(penetration_m);
    std::size_t k = 1;
    while (k + 1 < log_penetration.size() && x > log_penetration[k]) ++k;
    if (x < log_penetration.front()) return std::exp(log_force.front() + 1.5 * (x - log_penetration.front()));
    const double t = (x - log_penetration[k - 1]) / (log_penetration[k] - log_penetration[k - 1]);
    return std::exp(log_force[k - 1] + t * (log_force[k] - log_force[k - 1]));
  }
};

AloneLaw alone_law(const GapJoint& j, int rail, double load_N, double cell_m) {
  AloneLaw law;
  for (double fraction : {0.03, 0.06, 0.1, 0.15, 0.22, 0.3, 0.4, 0.5, 0.62, 0.75, 0.9, 1.1, 1.3}) {
    // One rail end alone: K / 2 (the wheel) + K / 2 (its own) = K, one
    // half-space whatever the bodies across the gap.
    const GapSolution s = gap_reference::solve_gap_contact(j, fraction * load_N, cell_m, Bodies::kOneHalfSpace,
                                                           steel_e_star_Pa(), 1e-9, rail);
    EXPECT_TRUE(s.converged);
    law.log_penetration.push_back(std::log(s.approach_m));
    law.log_force.push_back(std::log(fraction * load_N));
    law.centroid_x_m.push_back(s.centroid_x_m[static_cast<std::size_t>(rail)]);
  }
  return law;
}

/// The coupled model with each rail end's own law taken from the solver
/// (AloneLaw) instead of Hertz's: the coupling alone under test.
std::array<double, 2> coupled_with_own_laws(const GapJoint& j, double approach_m, const std::array<AloneLaw, 2>& law) {
  const EllipticalHertz hertz = wheel_on_crown();
  const std::array<gap_reference::TouchingPoint, 2> touching{gap_reference::touching_point(j, 0),
                                                             gap_reference::touching_point(j, 1)};
  const double h_min_m = std::min(touching[0].gap_m, touching[1].gap_m);
  const auto patch_at = [&](int i, double penetration_m) -> RailEndPatch {
    const auto k = static_cast<std::size_t>(i);
    if (!(penetration_m > 0.0)) return {touching[k].x_m, 0.0, 0.0};
    const double force_N = law[k].force_N(penetration_m);
    return {touching[k].x_m, hertz_patch(hertz, force_N).semi_axis_x_m, force_N};
  };
  const SpanningContact spanning = spanning_contact(
      {approach_m - (touching[0].gap_m - h_min_m), approach_m - (touching[1].gap_m - h_min_m)}, patch_at,
      2 * steel_e_star_Pa());
  return {spanning.share[0] * patch_at(0, spanning.effective_penetration_m[0]).force_N,
          spanning.share[1] * patch_at(1, spanning.effective_penetration_m[1]).force_N};
}

/// Each rail end its own law (the solver's, AloneLaw), its load not merged
/// with the other's (they lie on different bodies), and pressing the wheel
/// down at the other's touching point by Hertz's circular patch (2 E*,
/// hertz_patch_approach_m_per_N): the model change a gap would need, tried.
std::array<double, 2> apart_with_own_laws(const GapJoint& j, double approach_m, const std::array<AloneLaw, 2>& law,
                                          bool at_centroids) {
  const EllipticalHertz hertz = wheel_on_crown();
  const std::array<gap_reference::TouchingPoint, 2> touching{gap_reference::touching_point(j, 0),
                                                             gap_reference::touching_point(j, 1)};
  const double h_min_m = std::min(touching[0].gap_m, touching[1].gap_m);
  const std::array<double, 2> penetration_m{approach_m - (touching[0].gap_m - h_min_m),
                                            approach_m - (touching[1].gap_m - h_min_m)};
  std::array<double, 2> effective_m = penetration_m, force_N{};
  for (int round = 0; round < 200; ++round) {
    for (std::size_t i = 0; i < 2; ++i) force_N[i] = law[i].force_N(effective_m[i]);
    std::array<double, 2> next{};
    for (std::size_t i = 0; i < 2; ++i) {
      const std::size_t o = 1 - i;
      const double semi_m = force_N[o] > 0.0 ? hertz_patch(hertz, force_N[o]).semi_axis_x_m : 0.0;
      const double distance_m = at_centroids && force_N[i] > 0.0 && force_N[o] > 0.0
                                    ? law[i].centroid_at_m(force_N[i]) - law[o].centroid_at_m(force_N[o])
                                    : touching[i].x_m - touching[o].x_m;
      next[i] = penetration_m[i] - force_N[o] * hertz_patch_approach_m_per_N(distance_m, semi_m, 2 * steel_e_star_Pa());
    }
    for (std::size_t i = 0; i < 2; ++i) effective_m[i] = 0.5 * (effective_m[i] + next[i]);  // damped
  }
  for (std::size_t i = 0; i < 2; ++i) force_N[i] = law[i].force_N(effective_m[i]);
  return force_N;
}

/// A candidate law for a rail end whose patch the gap cuts, in closed form
/// as the force run could take it: Hertz's contact of the rail end's whole
/// paraboloid about its own vertex (which may lie over the gap), at the
/// penetration there, with only the part of Hertz's pressure that lies on
/// the rail end carried: the force is that part's, acting at its centroid.
struct CutPatch {
  double force_N = 0.0, centroid_x_m = 0.0, semi_length_m = 0.0;
};
CutPatch cut_hertz_patch(const GapJoint& j, int rail, double penetration_m) {
  const EllipticalHertz hertz = wheel_on_crown();
  const double sign = rail == 0 ? 1.0 : -1.0;
  const double vertex_x_m = j.wheel_x_m - sign * j.dip_rad * kRx;  // h's vertex on the rail end's plane
  const double vertex_gap_m = gap_reference::undeformed_gap_m(j, rail, vertex_x_m, 0.0);
  const double whole_m = penetration_m + (gap_reference::touching_point(j, rail).gap_m - vertex_gap_m);
  CutPatch out;
  if (!(penetration_m > 0.0)) return out;
  const double whole_N = std::pow(whole_m / hertz.hertz_constant_m_per_N2_3, 1.5);
  const HertzPatch patch = hertz_patch(hertz, whole_N);
  // p ~ sqrt(1 - u^2 - v^2) over the ellipse, by a 96 x 96 midpoint rule.
  double all = 0.0, on_rail = 0.0, moment = 0.0;
  const int n = 96;
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      const double u = -1.0 + (a + 0.5) * 2.0 / n, v = -1.0 + (b + 0.5) * 2.0 / n;
      const double w = 1.0 - u * u - v * v;
      if (w <= 0.0) continue;
      const double q = std::sqrt(w), x = vertex_x_m + u * patch.semi_axis_x_m, y = v * patch.semi_axis_y_m;
      all += q;
      if (gap_reference::rail_at(j, x, y) == rail) on_rail += q, moment += q * x;
    }
  }
  out.force_N = whole_N * on_rail / all;
  out.centroid_x_m = on_rail > 0.0 ? moment / on_rail : vertex_x_m;
  out.semi_length_m = patch.semi_axis_x_m;
  return out;
}

/// The coupled contact with cut_hertz_patch for each rail end, the loads
/// not merged across the gap, each pressing the wheel down at the other's
/// centroid through 2 E*: the model change tried.
std::array<double, 2> coupled_cut_patches(const GapJoint& j, double approach_m) {
  const std::array<gap_reference::TouchingPoint, 2> touching{gap_reference::touching_point(j, 0),
                                                             gap_reference::touching_point(j, 1)};
  const double h_min_m = std::min(touching[0].gap_m, touching[1].gap_m);
  const std::array<double, 2> penetration_m{approach_m - (touching[0].gap_m - h_min_m),
                                            approach_m - (touching[1].gap_m - h_min_m)};
  std::array<double, 2> effective_m = penetration_m;
  std::array<CutPatch, 2> patch{};
  for (int round = 0; round < 100; ++round) {
    for (std::size_t i = 0; i < 2; ++i) patch[i] = cut_hertz_patch(j, static_cast<int>(i), effective_m[i]);
    for (std::size_t i = 0; i < 2; ++i) {
      const std::size_t o = 1 - i;
      const double next_m =
          patch[i].force_N > 0.0 && patch[o].force_N > 0.0
              ? penetration_m[i] - patch[o].force_N * hertz_patch_approach_m_per_N(patch[i].centroid_x_m - patch[o].centroid_x_m,
                                                                                   patch[o].semi_length_m, 2 * steel_e_star_Pa())
              : penetration_m[i];
      effective_m[i] = 0.5 * (effective_m[i] + next_m);  // damped
    }
  }
  return {cut_hertz_patch(j, 0, effective_m[0]).force_N, cut_hertz_patch(j, 1, effective_m[1]).force_N};
}

/// Seeded random cases: gap 2-10 mm, cut 90, 45 or 30 deg, W 50-200 kN; the
/// dip on every other case 0.02-0.05 rad log-uniform (where the patches can
/// clear the gap), on the others 0 (a quarter) or 2.7e-3 to 0.05 rad
/// log-uniform; the wheel where both rail ends bear (their touching points'
/// gaps within 70 % of Hertz's approach under W of each other,
/// rejection-sampled over x_w in +-20 mm).
std::vector<Sample> random_samples(unsigned seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double G = wheel_on_crown().hertz_constant_m_per_N2_3;
  std::vector<Sample> out;
  while (static_cast<int>(out.size()) < count) {
    Sample c;
    c.joint.gap_m = 0.002 + 0.008 * unit(rng);
    c.joint.cut_angle_rad = rad(std::array<double, 3>{90.0, 45.0, 30.0}[static_cast<std::size_t>(3 * unit(rng)) % 3]);
    // Every other case a large dip (0.02-0.05 rad), where the patches can
    // clear the gap: the coupling alone under test.
    const double kind = unit(rng);
    c.joint.dip_rad = out.size() % 2 == 1 ? 0.02 * std::pow(2.5, kind) : (kind < 0.25 ? 0.0 : 1e-3 * std::pow(50.0, kind));
    c.load_N = 50e3 + 150e3 * unit(rng);
    c.joint.wheel_x_m = -0.02 + 0.04 * unit(rng);
    const double h0 = gap_reference::touching_point(c.joint, 0).gap_m, h1 = gap_reference::touching_point(c.joint, 1).gap_m;
    if (std::abs(h0 - h1) < 0.7 * G * std::pow(c.load_N, 2.0 / 3.0)) out.push_back(c);
  }
  return out;
}

struct Stats {
  double median = 0.0, p90 = 0.0, max = 0.0, min = 0.0;
  std::size_t count = 0;
};
Stats stats_of(std::vector<double> v) {
  Stats s;
  s.count = v.size();
  if (v.empty()) return s;
  s.min = *std::min_element(v.begin(), v.end());
  s.max = *std::max_element(v.begin(), v.end());
  for (double& x : v) x = std::abs(x);
  std::sort(v.begin(), v.end());
  s.median = v[v.size() / 2];
  s.p90 = v[std::min(v.size() - 1, static_cast<std::size_t>(std::ceil(0.9 * static_cast<double>(v.size()))) - 1)];
  return s;
}

void print_stats(const char* what, const std::vector<double>& v) {
  const Stats s = stats_of(v);
  if (s.count == 0) {
    std::printf("  %-62s n  0\n", what);
    return;
  }
  std::printf("  %-62s n %2zu  |median| %6.2f %%  p90 %6.2f %%  range %+7.2f .. %+7.2f %%\n", what, s.count,
              100 * s.median, 100 * s.p90, 100 * s.min, 100 * *std::max_element(v.begin(), v.end()));
}

void random_study(unsigned seed, int count, double cell_m) {
  std::printf("seed %u, %d cases, %.2f mm cells\n", seed, count, 1e3 * cell_m);
  // Classes: both patches clear of the gap (each rail end's own law is
  // Hertz's: the coupling under test; they are then more than two patch
  // semi-lengths apart, g + a_0 + a_1), or a patch cut by the gap (the
  // touching point at the cut's edge or its Hertz ellipse over the gap).
  std::vector<double> ends[2], totals[2], own_totals[2], unmerged_totals[2], centroid_totals[2], one_totals[2];
  std::vector<double> cut_by_edges[3], cut_by_gap[3], springs[2], cut_totals[2], cut_ends[2];
  for (const Sample& c : random_samples(seed, count)) {
    const Row r = evaluate(c, cell_m);
    const GapSolution apart =
        gap_reference::solve_gap_contact(c.joint, c.load_N, cell_m, Bodies::kRailEndsApart, steel_e_star_Pa());
    const std::array<AloneLaw, 2> laws{alone_law(c.joint, 0, c.load_N, cell_m), alone_law(c.joint, 1, c.load_N, cell_m)};
    const auto own = coupled_with_own_laws(c.joint, apart.approach_m, laws);
    const double own_total = (own[0] + own[1]) / c.load_N - 1.0;
    const auto unmerged = apart_with_own_laws(c.joint, apart.approach_m, laws, false);
    const double unmerged_total = (unmerged[0] + unmerged[1]) / c.load_N - 1.0;
    const auto centroids = apart_with_own_laws(c.joint, apart.approach_m, laws, true);
    const double centroid_total = (centroids[0] + centroids[1]) / c.load_N - 1.0;
    const auto cut = coupled_cut_patches(c.joint, apart.approach_m);
    const double cut_total = (cut[0] + cut[1]) / c.load_N - 1.0;
    print_row(r);
    std::printf(
        "      own laws: %+7.4f %+7.4f total %+7.4f | own laws, not merged: total %+7.4f | at centroids %+7.4f | cut "
        "Hertz patches: %+7.4f %+7.4f total %+7.4f\n",
        (own[0] - apart.force_N[0]) / c.load_N, (own[1] - apart.force_N[1]) / c.load_N, own_total, unmerged_total,
        centroid_total, (cut[0] - apart.force_N[0]) / c.load_N, (cut[1] - apart.force_N[1]) / c.load_N, cut_total);
    const int k = r.apart.clear ? 0 : 1;
    if (r.apart.clear) {
      EXPECT_GT(r.apart.apart, 2.0) << describe(c);
    }
    ends[k].push_back(r.apart.end_error[0]);
    ends[k].push_back(r.apart.end_error[1]);
    totals[k].push_back(r.apart.total_error);
    if (k == 0) {
      // Patches clear of the gap: the force run's vouched 1 % (measured
      // within 0.14 % of W on seeds 1 and 2).
      EXPECT_LT(std::abs(r.apart.end_error[0]), 1e-2) << describe(c);
      EXPECT_LT(std::abs(r.apart.end_error[1]), 1e-2) << describe(c);
      EXPECT_LT(std::abs(r.apart.total_error), 1e-2) << describe(c);
      EXPECT_LT(std::abs(r.one.total_error), 1e-2) << describe(c);
    }
    own_totals[k].push_back(own_total);
    unmerged_totals[k].push_back(unmerged_total);
    centroid_totals[k].push_back(centroid_total);
    cut_totals[k].push_back(cut_total);
    cut_ends[k].push_back((cut[0] - apart.force_N[0]) / c.load_N);
    cut_ends[k].push_back((cut[1] - apart.force_N[1]) / c.load_N);
    one_totals[k].push_back(r.one.total_error);
    springs[k].push_back(r.apart.uncoupled_error);
    if (k == 1) {
      cut_by_edges[r.apart.edges].push_back(r.apart.total_error);
      cut_by_gap[c.joint.gap_m < 0.004 ? 0 : (c.joint.gap_m < 0.007 ? 1 : 2)].push_back(r.apart.total_error);
    }
  }
  const char* names[2] = {"patches clear of the gap", "a patch cut by the gap"};
  for (int k = 0; k < 2; ++k) {
    std::printf("%s\n", names[k]);
    print_stats("each end, model (2 E*) vs rail ends apart [of W]", ends[k]);
    print_stats("total, model (2 E*) vs rail ends apart", totals[k]);
    print_stats("total, model with the solver's own laws vs rail ends apart", own_totals[k]);
    print_stats("total, own laws, not merged, 2 E* far field vs rail ends apart", unmerged_totals[k]);
    print_stats("total, the same, coupled between the loads' centroids", centroid_totals[k]);
    print_stats("total, model (E*) vs one half-space", one_totals[k]);
    print_stats("total, sum of two springs vs rail ends apart", springs[k]);
    print_stats("each end, cut Hertz patches, not merged, at centroids", cut_ends[k]);
    print_stats("total, cut Hertz patches, not merged, at centroids", cut_totals[k]);
  }
  std::printf("a patch cut by the gap, total, model (2 E*) vs rail ends apart, by where\n");
  print_stats("touching points on the faces, a patch over the gap", cut_by_edges[0]);
  print_stats("one touching point at a cut's edge", cut_by_edges[1]);
  print_stats("both at the cut's edges (the wheel over the gap)", cut_by_edges[2]);
  print_stats("gap 2-4 mm", cut_by_gap[0]);
  print_stats("gap 4-7 mm", cut_by_gap[1]);
  print_stats("gap 7-10 mm", cut_by_gap[2]);
}

TEST(RailEndShareGapStudy, GridConvergence) {
  // The quantity compared (each rail end's force from the solver, and the
  // model's error at the solver's approach, both over W) on 0.5, 0.4 and
  // 0.2 mm cells (the study's 0.4 halved), eight cases of seed 3.
  std::vector<double> moved_05, moved_04;
  for (const Sample& c : random_samples(3, 8)) {
    std::array<GapSolution, 3> s;
    std::array<double, 3> error{};
    const std::array<double, 3> cells{0.5e-3, 0.4e-3, 0.2e-3};
    for (std::size_t k = 0; k < 3; ++k) {
      s[k] = gap_reference::solve_gap_contact(c.joint, c.load_N, cells[k], Bodies::kRailEndsApart, steel_e_star_Pa());
      ASSERT_TRUE(s[k].converged);
      error[k] = compare(c.joint, c.load_N, s[k], 2 * steel_e_star_Pa()).total_error;
    }
    std::printf("%s  rail 0's share %.4f %.4f %.4f  model total %+7.4f %+7.4f %+7.4f  (0.5, 0.4, 0.2 mm; %dx%d cells at 0.2)\n",
                describe(c).c_str(), s[0].force_N[0] / c.load_N, s[1].force_N[0] / c.load_N, s[2].force_N[0] / c.load_N,
                error[0], error[1], error[2], s[2].cells_x, s[2].cells_y);
    moved_05.push_back(std::max(std::abs(s[0].force_N[0] - s[2].force_N[0]) / c.load_N, std::abs(error[0] - error[2])));
    moved_04.push_back(std::max(std::abs(s[1].force_N[0] - s[2].force_N[0]) / c.load_N, std::abs(error[1] - error[2])));
  }
  const double moved_04_max = *std::max_element(moved_04.begin(), moved_04.end());
  std::printf("largest move to 0.2 mm [of W]: from 0.5 mm %.4f, from 0.4 mm %.4f\n",
              *std::max_element(moved_05.begin(), moved_05.end()), moved_04_max);
  // Measured 0.0115 (a corner contact on a square cut, whose edge the cell
  // centres place to half a cell): against disagreements of 10-60 % there.
  EXPECT_LT(moved_04_max, 0.02);
}

TEST(RailEndShareGapStudy, CutPatchLaw) {
  // One rail end alone, its paraboloid's vertex a distance d from the cut's
  // edge (d < 0: over the gap), 150 kN: its force over Hertz's at the
  // vertex's penetration (the approach plus the vertex's gap below the
  // touching point). Hertz's scaling makes it a function of d / a alone
  // (a: Hertz's semi-length at that penetration) for a given cut: the table
  // a force run could take for a rail end whose patch the gap cuts.
  // Measured at 0.4 mm cells: 0.77-0.78 at d = 0 on all three cuts, 0.44
  // (90 deg) to 0.58 (30 deg) at d = -0.55 a, 1.00 at d = a on the square
  // cut; taking only the part of Hertz's pressure on the rail end gives 0.5
  // at d = 0: a cut patch is stiffer than that.
  const EllipticalHertz hertz = wheel_on_crown();
  const double load_N = 150e3;
  for (const double angle_deg : {90.0, 45.0, 30.0}) {
    std::printf("cut %2.0f deg:", angle_deg);
    double last = 0.0;
    for (const double d_mm : {-6.0, -4.0, -2.0, -1.0, 0.0, 1.0, 2.0, 4.0, 6.0, 8.0}) {
      // Rail end 1 (s > g / 2), flat: its vertex is the wheel's lowest point.
      const GapJoint j{0.006, rad(angle_deg), 0.0, 0.003 / std::sin(rad(angle_deg)) + 1e-3 * d_mm};
      const GapSolution s =
          gap_reference::solve_gap_contact(j, load_N, 0.4e-3, Bodies::kOneHalfSpace, steel_e_star_Pa(), 1e-9, 1);
      const double vertex_m = s.approach_m + gap_reference::touching_point(j, 1).gap_m -
                              gap_reference::undeformed_gap_m(j, 1, j.wheel_x_m, 0.0);
      const double hertz_N = std::pow(vertex_m / hertz.hertz_constant_m_per_N2_3, 1.5);
      const double a_m = hertz_patch(hertz, hertz_N).semi_axis_x_m;
      std::printf("  d/a %+5.2f: %.3f", 1e-3 * d_mm / a_m, load_N / hertz_N);
      EXPECT_GT(load_N / hertz_N, last);  // more of the patch on the rail end, nearer Hertz
      last = load_N / hertz_N;
      EXPECT_LT(last, 1.0 + 2e-3);  // never stiffer than the whole patch (to the cells' 2e-3)
    }
    std::printf("\n");
    if (angle_deg == 90.0) {
      EXPECT_NEAR(last, 1.0, 2e-3);  // the patch clear of the cut: Hertz
    }
  }
  // Hertz's scaling: at 60 kN, lengths (150 / 60)^(1/3) shorter, the same
  // ratio at the same d / a (measured 0.519 and 0.514: the cells, fewer
  // across the smaller patch).
  std::array<double, 2> ratio{};
  for (const double scale : {1.0, std::cbrt(60.0 / 150.0)}) {
    const double load_here_N = load_N * scale * scale * scale;
    const GapJoint j{0.006, rad(90), 0.0, 0.003 - 0.004 * scale};
    const GapSolution s =
        gap_reference::solve_gap_contact(j, load_here_N, 0.4e-3, Bodies::kOneHalfSpace, steel_e_star_Pa(), 1e-9, 1);
    const double vertex_m = s.approach_m + gap_reference::touching_point(j, 1).gap_m -
                            gap_reference::undeformed_gap_m(j, 1, j.wheel_x_m, 0.0);
    ratio[scale == 1.0 ? 0 : 1] = load_here_N / std::pow(vertex_m / hertz.hertz_constant_m_per_N2_3, 1.5);
  }
  std::printf("square cut, vertex 4 mm over the gap at 150 kN: %.4f; scaled to 60 kN: %.4f\n", ratio[0], ratio[1]);
  EXPECT_NEAR(ratio[1], ratio[0], 2e-2);
}

TEST(RailEndShareGapStudy, SolveCost) {
  // What a boundary-element solve per force evaluation would cost a force
  // run where the gap cuts a patch: the wall time and iterations of one
  // solve (printed, not asserted) on seed 1's cut cases at 0.4 and 0.2 mm
  // cells: the reference's two-body solve (rail ends apart, plain
  // Polonsky-Keer) at its 1e-9 and at 1e-6, and the models/ solver (one
  // half-space, preconditioned) cold and warm from the solution one step of
  // travel before (0.2 mm: 50 m/s x 4e-6 s) on the same grid. Each is
  // load-controlled; the run's approach-controlled contact would need a
  // secant on the load around it (2-3 warm solves).
  using Clock = std::chrono::steady_clock;
  const auto ms_since = [](Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  };
  const double e_star = steel_e_star_Pa();
  int shown = 0;
  for (const Sample& c : random_samples(1, 40)) {
    const Row probe = evaluate(c, 0.5e-3);
    if (probe.apart.clear) continue;
    if (++shown > 10) break;
    for (const double cell_m : {0.4e-3, 0.2e-3}) {
      Clock::time_point t0 = Clock::now();
      const GapSolution tight = gap_reference::solve_gap_contact(c.joint, c.load_N, cell_m, Bodies::kRailEndsApart, e_star, 1e-9);
      const double tight_ms = ms_since(t0);
      t0 = Clock::now();
      const GapSolution loose = gap_reference::solve_gap_contact(c.joint, c.load_N, cell_m, Bodies::kRailEndsApart, e_star, 1e-6);
      const double loose_ms = ms_since(t0);
      // The models/ solver, one half-space, its box 1.5 x the first reach.
      const double h_min_m = gap_reference::lowest_gap_m(c.joint);
      const gap_reference::GridBox box =
          gap_reference::grid_box(c.joint, h_min_m, 1.5 * gap_reference::first_reach_m(c.load_N), cell_m);
      GapJoint before = c.joint;
      before.wheel_x_m -= 0.2e-3;
      const HalfSpaceConvolution convolution(box.nx, box.ny, cell_m, cell_m, e_star);
      NormalContactProblem problem;
      problem.normal_force_N = c.load_N;
      problem.tolerance = 1e-6;
      const auto grid_before = gap_reference::gap_grid_on(before, box, gap_reference::lowest_gap_m(before), cell_m);
      problem.gap_m = grid_before.gap_m;
      problem.no_surface = !grid_before.bears;
      const NormalContactSolution previous = solve_normal_contact(problem, convolution);
      const auto grid = gap_reference::gap_grid_on(c.joint, box, h_min_m, cell_m);
      problem.gap_m = grid.gap_m;
      problem.no_surface = !grid.bears;
      t0 = Clock::now();
      const NormalContactSolution cold = solve_normal_contact(problem, convolution);
      const double cold_ms = ms_since(t0);
      problem.initial_pressure_Pa = previous.pressure_Pa;
      t0 = Clock::now();
      const NormalContactSolution warm = solve_normal_contact(problem, convolution);
      const double warm_ms = ms_since(t0);
      const double cold_0 = grid.on_0.select(cold.pressure_Pa, 0.0).sum() * cell_m * cell_m / c.load_N;
      const double warm_0 = grid.on_0.select(warm.pressure_Pa, 0.0).sum() * cell_m * cell_m / c.load_N;
      std::printf(
          "%s %.1f mm cells %3dx%3d | apart 1e-9: %5d it %8.2f ms, 1e-6: %5d it %7.2f ms, share 0 %.4f/%.4f | one "
          "half-space %dx%d: cold %3d it %6.2f ms, warm %3d it %6.2f ms, share 0 %.4f/%.4f\n",
          describe(c).c_str(), 1e3 * cell_m, tight.cells_x, tight.cells_y, tight.iterations, tight_ms, loose.iterations,
          loose_ms, tight.force_N[0] / c.load_N, loose.force_N[0] / c.load_N, box.nx, box.ny, cold.iterations, cold_ms,
          warm.iterations, warm_ms, cold_0, warm_0);
      EXPECT_TRUE(tight.converged && loose.converged && cold.converged && warm.converged);
      // A warm start changes the work, not the answer (both to the 1e-6
      // tolerance: shares measured equal to 1e-4 of W as printed), and buys
      // about half the iterations (measured 10-14 warm against 19-27 cold).
      EXPECT_NEAR(warm_0, cold_0, 1e-4);
      EXPECT_LT(warm.iterations, cold.iterations);
    }
  }
}

TEST(RailEndShareGapStudy, TableSpacingAlongTheTrack) {
  // A per-run table of the pair's solution over the wheel's position (the
  // geometry depends on x alone): how fine must it be? The wheel swept
  // across level-rail gaps (where the flag falls) at a fixed load in 0.2 mm
  // steps, the two-body solve (0.4 mm cells) at each; each rail end's share
  // and the approach interpolated linearly from every 2nd, 4th and 8th
  // position (0.4, 0.8, 1.6 mm) against the solve between. Measured: the
  // shares to 0.07-0.20 %, 0.23-0.43 % and 0.7-1.5 % of W (the 0.4 mm
  // cells' own steps in it too); 0.8 mm keeps a table within the run's
  // vouched 1 %. The sweep runs from one rail end alone to the other.
  const double e_star = steel_e_star_Pa(), load_N = 120e3, step_m = 0.2e-3;
  const EllipticalHertz hertz = wheel_on_crown();
  const double a_m = hertz_patch(hertz, load_N).semi_axis_x_m;
  for (const auto& [gap_m, angle_deg] : std::vector<std::pair<double, double>>{{0.003, 90}, {0.008, 90}, {0.004, 45}, {0.008, 30}}) {
    const double half_m = 0.5 * gap_m / std::sin(rad(angle_deg)) + a_m;
    std::vector<double> share, approach;
    for (double x_m = -half_m; x_m <= half_m + 1e-12; x_m += step_m) {
      const GapJoint j{gap_m, rad(angle_deg), 0.0, x_m};
      const GapSolution s = gap_reference::solve_gap_contact(j, load_N, 0.4e-3, Bodies::kRailEndsApart, e_star, 1e-6);
      ASSERT_TRUE(s.converged);
      share.push_back(s.force_N[0] / load_N);
      approach.push_back(s.approach_m + gap_reference::lowest_gap_m(j));  // from the wheel's lowest point's level
    }
    std::printf("gap %.0f mm %2.0f deg, x_w +-%.1f mm, %zu positions:", 1e3 * gap_m, angle_deg, 1e3 * half_m, share.size());
    for (const std::size_t every : {2u, 4u, 8u}) {
      double worst_share = 0.0, worst_approach = 0.0;
      for (std::size_t k = 0; k + every < share.size(); k += every) {
        for (std::size_t m = 1; m < every; ++m) {
          const double t = static_cast<double>(m) / static_cast<double>(every);
          worst_share = std::max(worst_share, std::abs((1 - t) * share[k] + t * share[k + every] - share[k + m]));
          worst_approach = std::max(worst_approach, std::abs((1 - t) * approach[k] + t * approach[k + every] - approach[k + m]) /
                                                        approach[k + m]);
        }
      }
      std::printf("  every %.1f mm: share %.4f of W, approach %.4f", 1e3 * step_m * static_cast<double>(every), worst_share,
                  worst_approach);
      if (every == 4) {
        EXPECT_LT(worst_share, 1e-2);
      }
    }
    std::printf("\n");
    EXPECT_GT(*std::max_element(share.begin(), share.end()), 0.99);
    EXPECT_LT(*std::min_element(share.begin(), share.end()), 0.01);
  }
}

TEST(RailEndShareGapStudy, RandomSeed1) { random_study(1, 40, 0.4e-3); }
TEST(RailEndShareGapStudy, RandomSeed2) { random_study(2, 40, 0.4e-3); }

}  // namespace
}  // namespace railjoint
