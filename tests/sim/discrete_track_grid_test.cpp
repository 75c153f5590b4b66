// The discrete track's grid (track.nodes_per_bay): the rail between nodes
// is a central fourth difference, so its static line, and with it the rail
// seat's force, is off the Euler-Bernoulli beam's by O(h^2). Measured
// against an exact beam on the same supports, the error must fall 4x per
// halving of h (docs/forces.md, "The rail's grid").

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "sim/discrete_track.h"
#include "sim/elastic_track_settings.h"
#include "sim/sim_settings.h"
#include "tests/sim/hermite_beam_reference.h"

namespace railjoint {
namespace {

// The largest rail-seat force under a static downward load at the joint
// (x = 0, midway between two sleepers), less one bay of rail's weight
// (rail_seat_N holds the weight the seat carries unloaded) [N].
double seat_force_under_load_N(int nodes_per_bay, double load_N) {
  DiscreteTrackSettings settings;
  settings.nodes_per_bay = nodes_per_bay;
  DiscreteTrack track(settings, 15.0);  // 18 decay lengths 1 / beta_f each way: the ends change nothing
  track.rest_under(load_N, 0.0);
  double seat_N = 0.0;
  for (std::size_t j = 0; j < track.sleeper_count(); ++j) seat_N = std::max(seat_N, track.rail_seat_N(j));
  return seat_N - settings.mass_per_length_kg_per_m * settings.sleeper_spacing_m * kStandardGravity_m_per_s2;
}

// The exact value: cubic Hermite elements (tests/sim/hermite_beam_reference.h,
// no sim/ code) are the Euler-Bernoulli beam's own solution between nodal
// forces, so with nodes at the sleepers and the joint they are exact at any
// element count. On the defaults (EI 6.38e6 N m^2, pad 200e6 and ballast
// 40e6 N/m in series = 3.333e7 N/m every 0.6 m) under P0 = 112.5 kN + 750 kg
// x 9.81 m/s^2 = 119857.5 N the nearest seats carry 39203.59 N each (the
// audit's beam_static.py, 80 bays of 12 elements: 39203.5913 N; with the
// bay's rail weight 60.2 x 0.6 x 9.81 = 354.34 N, 39557.93 N against main's
// 39582.98 N from simulate). A Winkler foundation k/s = 5.556e7 N/m^2
// (beta_f = 1.2147 / m) gives s P beta_f / 2 e^(-beta_f x)(cos + sin)(beta_f x)
// at x = 0.3 m: 39158 N, 1.2e-3 below: the supports' discreteness.
TEST(DiscreteTrackGrid, TheStaticRailSeatForceConvergesToTheExactBeamAtSecondOrder) {
  const double load_N = 119857.5;
  testing_reference::HermiteBeamCrossing beam;
  beam.elements_per_bay = 2;
  beam.half_length_m = 15.0;
  const testing_reference::HermiteBeam exact_beam(beam);
  Eigen::VectorXd u = exact_beam.static_state(load_N, 0.0, true);
  exact_beam.settle_sleepers(u);
  const Eigen::VectorXd at_rest = Eigen::VectorXd::Zero(u.size());
  double exact_N = 0.0;
  for (std::size_t j = 0; j < exact_beam.sleeper_count(); ++j) {
    exact_N = std::max(exact_N, exact_beam.pad_N(u, at_rest, j));
  }
  std::printf("exact beam: rail seat %.4f N\n", exact_N);
  EXPECT_NEAR(exact_N, 39203.59, 0.01);  // the audit's own solve, above

  std::vector<double> error;
  for (const int nodes : {8, 16, 32, 64}) {
    error.push_back(seat_force_under_load_N(nodes, load_N) / exact_N - 1.0);
    std::printf("%2d nodes a bay: rail seat %.4f N, error %+.3e\n", nodes, (1.0 + error.back()) * exact_N,
                error.back());
  }
  // 8 nodes a bay: +6.39e-4 (the audit's finite-difference chain +6.4e-4; +6.3e-4 in simulate's output,
  // where the bay's weight is part of the force). Measured ratios 3.996-3.999: tolerances ~10x the residual.
  EXPECT_NEAR(error[0], 6.39e-4, 0.1e-4);
  for (std::size_t i = 1; i < error.size(); ++i) {
    const double ratio = error[i - 1] / error[i];
    std::printf("error ratio %d -> %d nodes: %.3f (second order: 4)\n", 8 << (i - 1), 8 << i, ratio);
    EXPECT_NEAR(ratio, 4.0, 0.05);
  }
}

}  // namespace
}  // namespace railjoint
