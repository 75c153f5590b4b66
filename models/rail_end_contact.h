#pragma once
// The solved contact of a wheel crossing the end-post gap (the local model
// of thesis chapters 5-6 with the patch computed instead of prescribed): at
// each wheel position the undeformed gap between the wheel's tread
// (wheel_tread.h: radius, cone, measured) and the two rail ends (rail_top.h:
// crown or 60E1 head, the dip, the cut at theta, no rail in the end-post
// gap), the outgoing end raised by a height mismatch, on a grid that follows
// the contact; the pressure from the boundary-element solver
// (normal_contact_solver.h), elastic or capped.
//
// Limit: both bodies are half-spaces. A rail end is a quarter space: its
// free edge at the cut is more compliant than the half-space there, so the
// solved edge peak is an upper estimate of the elastic one.

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "models/parameters.h"

namespace railjoint {

/// The largest window_over_axes a scene takes, or a grown window reaches:
/// past it Hertz's patch spans under 8 of the default 128 x 96 cells [-].
inline constexpr double kMaxWindowOverAxes = 20.0;

struct RailEndContactSettings {
  int cells_x = 128;                ///< grid cells along the track
  int cells_y = 96;                 ///< grid cells across
  double window_over_axes = 2.5;    ///< grid size over Hertz's full axes on the incoming rail at the sizing load [-]
  std::optional<double> yield_pressure_Pa;  ///< the cap; none: elastic
  double height_mismatch_m = 0.0;   ///< the outgoing rail end above the incoming one [m]
  double youngs_modulus_Pa = 210e9; ///< E of wheel and rail [Pa]
  double poisson_ratio = 0.3;       ///< nu of wheel and rail [-]
  double edge_average_length_m = 1e-3;  ///< L of the edge load (rail_end_edge_load.h) [m]
};

/// The undeformed gap on a grid: cell (i, j) is centred at
/// (x0 + i dx, y0 + j dy).
struct RailEndGap {
  Eigen::ArrayXXd gap_m;  ///< wheel above rail, less its minimum over the surface [m]
  Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic> no_surface;  ///< end-post gap and beyond the head
  Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic> incoming;    ///< cells on the incoming rail end
  double x0_m = 0.0, y0_m = 0.0, dx_m = 0.0, dy_m = 0.0;
};

/// The gap for the wheel's centre plane at x = x_wheel_m on a grid of
/// settings.cells_x x cells_y cells of dx x dy centred on (x_centre_m, y_centre_m).
RailEndGap rail_end_gap(const JointParams& joint, const WheelParams& wheel, const RailEndContactSettings& settings,
                        double x_wheel_m, double x_centre_m, double y_centre_m, double dx_m, double dy_m);

struct RailEndStep {
  double x_wheel_m = 0.0;
  double t_s = 0.0;
  double normal_force_N = 0.0;  ///< the load at this step (0: the wheel in flight, no contact)
  double max_pressure_Pa = 0.0;
  double x_at_max_m = 0.0, y_at_max_m = 0.0;  ///< the peak's cell centre
  double contact_area_m2 = 0.0;
  double plastic_area_m2 = 0.0;
  double force_incoming_N = 0.0;
  double force_outgoing_N = 0.0;
  double approach_m = 0.0;
  int iterations = 0;
  bool converged = false;
  /// A cell in contact beside the end-post gap, the head's side or the other
  /// rail end: the contact reaches a sharp edge, where the elastic pressure is
  /// a square-root singularity (the flat punch's) and a cell's pressure grows
  /// as the cells shrink (p ~ h^-1/2).
  bool contact_at_edge = false;
  /// The mean pressure on the worst L x L square of face at a cut edge
  /// (rail_end_edge_load.h): the elastic edge's measure that converges
  /// (elastic only: 0 under a cap).
  double edge_pressure_Pa = 0.0;
  double x_of_edge_pressure_m = 0.0, y_of_edge_pressure_m = 0.0;  ///< that square's centre on the cut
  int edge_rail = 0;  ///< its rail end: 0 incoming, 1 outgoing
};

/// The largest |change| at which a run vouches for its edge pressure [-].
/// On seeded random crossings the edge pressure moves 1-3 % a halving (p90
/// 3.1 %, max 5 %), and about half as much at the next; the values vouched
/// for on 64 x 48 cells were within 2.3 % of 256 x 192 cells' (two seeds,
/// docs/rail-end-contact.md).
inline constexpr double kEdgeGridTolerance = 0.03;

/// The edge pressure's grid check: the peak step solved again on the same
/// window at half the cells' size (twice the cells each way), its edge
/// pressure compared with this grid's at the same wheel position.
struct EdgePressureGridCheck {
  double fine_Pa = 0.0;      ///< the peak step's edge pressure at half the cells' size [Pa]
  double change = 0.0;       ///< the crossing's max edge pressure on these cells against fine_Pa: coarse / fine - 1 [-]
  bool converged = false;    ///< the fine solve reached the solver's tolerance, with contact at a cut
  int fine_iterations = 0;   ///< the fine solve's iterations (its cost)
  bool vouches() const { return converged && std::abs(change) <= kEdgeGridTolerance; }
};

struct RailEndCrossing {
  std::vector<RailEndStep> steps;
  double hertz_semi_axis_x_m = 0.0, hertz_semi_axis_y_m = 0.0;  ///< sized the grid
  double contact_y_m = 0.0;            ///< lateral position of the contact (the grid's centre line)
  /// The highest pressure (then the largest plastic area); where the largest
  /// pressure is singular (below), the highest edge pressure instead: the
  /// largest cell's step moves with the grid. Of steps that tie (kPeakTie)
  /// the first.
  std::size_t peak_step = 0;
  std::vector<std::size_t> tied_peak_steps;  ///< the other steps that tie it, in order
  double initial_max_pressure_Pa = 0.0;  ///< first step: the patch on the incoming rail alone
  double initial_area_m2 = 0.0;
  double max_plastic_area_m2 = 0.0;
  bool all_converged = true;
  /// Elastic (no cap) and some step's contact at an edge: the crossing's
  /// largest pressure is the grid's, not the contact's (it has no bound).
  bool max_pressure_singular = false;
  /// Some step's elastic contact reaches an edge other than the cuts (the
  /// head's side, the tread's rim), which the edge pressure does not measure.
  bool contact_at_side = false;
  /// Where max_pressure_singular and not contact_at_side: the edge pressure's grid check.
  std::optional<EdgePressureGridCheck> edge_grid_check;
  RailEndGap peak_gap;                 ///< the gap at the peak step
  Eigen::ArrayXXd peak_pressure_Pa;    ///< the pressure map at the peak step
};

/// Two steps' peaks (pressure, then plastic area) tie when they agree within
/// this fraction: a symmetric crossing's mirror steps agree to 1e-10 (the
/// solver's tolerance; measured 4e-11 to 9e-11 on table6_1_solved at
/// 64 x 48 to 256 x 192 cells), neighbouring steps at the top differ by 2e-4
/// and more.
constexpr double kPeakTie = 1e-6;

/// The crossing in `steps` wheel positions from where the patch lies on the
/// incoming rail alone to where it lies on the outgoing one, under the
/// constant load N at speed v (t = x / v). Throws InputError (keys
/// contact_patch.*, joint.*) for what it cannot describe: a head without a
/// crown under a cylinder (a line contact), a patch the grid cannot hold.
RailEndCrossing rail_end_crossing(const JointParams& joint, const WheelParams& wheel,
                                  const RailEndContactSettings& settings, double normal_force_N, int steps);

/// The normal load at each wheel position x [m]: a force run's N(x).
using NormalForceAt = std::function<double(double x_wheel_m)>;

/// The same crossing under a load that changes with the wheel's position
/// (a force run's contact force, so that the rail end sees P1 where the
/// wheel was over it). The grid and the traversal are sized by Hertz's
/// patch under `sizing_force_N` (a force run's static load: the grid and the
/// positions of the static crossing under it); a step whose load is 0 (the
/// wheel in flight) has no contact.
/// Throws InputError as above, and under contact_patch.normal_force for a
/// negative or non-finite load.
RailEndCrossing rail_end_crossing(const JointParams& joint, const WheelParams& wheel,
                                  const RailEndContactSettings& settings, const NormalForceAt& normal_force_N,
                                  double sizing_force_N, int steps);

}  // namespace railjoint
