#pragma once
// Frictionless normal contact between two elastic bodies, each a half-space,
// on a regular grid of rectangular cells (a boundary-element method): given
// the undeformed gap h and the total load W, find the pressure p and the
// approach delta with
//   g = h + u(p) - delta >= 0,  p >= 0,  p g = 0,  sum(p) dA = W,
// u the surfaces' elastic approach (models/half_space_convolution.h). Solved
// by Polonsky and Keer's conjugate gradient (Wear 231, 1999, 206-219) on the
// cells in contact, the load held at every iteration, preconditioned by an
// approximate inverse of the influence operator, E* |k| / 2 applied by FFT
// (Vollebregt, J. Comput. Phys. 257, 2014, 333-351, preconditions the same
// kind of iteration by an FFT-applied approximate inverse of his own, with
// deflation; this one is simpler): the iterations hardly grow with the grid
// (20-26 cold from 64 x 64 to 256 x 256, against 55-100).
//
// Elastic-perfectly-plastic interface (optional cap p_y): p <= p_y as well;
// cells at the cap leave the elastic set and the load they cannot take
// spreads to their neighbours, so the patch grows. Polonsky and Keer's
// iteration holds the load by scaling, which under the cap is no projection
// and can cycle; where it does not converge, the capped problem is solved
// as the convex quadratic programme it is, by an accelerated projected
// gradient that converges from any start. This caps the pressure
// only: it ignores the subsurface plastic zone and the residual stresses that
// full elastic-plastic methods compute (Jacq et al., J. Tribology 124, 2002).
//
// Cells marked no_surface (the end-post gap) carry no pressure whatever
// their gap.

#include <optional>
#include <string>

#include <Eigen/Core>

#include "models/half_space_convolution.h"
#include "support/input_error.h"

namespace railjoint {

/// The keys bad input is reported under: the Python argument names by
/// default, a scene's keys where a scene asked for the solve.
struct NormalContactKeys {
  std::string load = "load_N";
  std::string yield_pressure = "yield_pressure_Pa";
  std::string grid = "cell_size_m";
  std::string gap = "gap_m";
  /// How to make the grid larger, in the caller's words.
  std::string larger_grid = "more cells, or larger ones: cell_size_m";
};

/// A patch that reaches the grid's border: it would have spread further on a
/// larger grid. Apart from other bad input so that a caller that sizes the
/// grid itself can size it again.
struct PatchReachesBorder : InputError {
  using InputError::InputError;
};

struct NormalContactProblem {
  Eigen::ArrayXXd gap_m;   ///< undeformed gap, nx x ny (row i: x_i, column j: y_j) [m]
  Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic> no_surface;  ///< empty, or nx x ny: true = no surface there
  double normal_force_N = 0.0;                ///< total load W [N]
  std::optional<double> yield_pressure_Pa;    ///< cap p_y [Pa]; none: elastic
  Eigen::ArrayXXd initial_pressure_Pa;        ///< empty, or nx x ny: a warm start (e.g. the previous step's)
  double tolerance = 1e-10;                   ///< on sum|p_k - p_(k-1)| / sum p_k [-]
  int max_iterations = 5000;
  int min_cells_across = 8;  ///< fewer cells across the patch (x or y): refused as too coarse
  /// The conjugate gradient preconditioned by HalfSpaceConvolution::
  /// approximate_pressure_Pa until a cell reaches the cap: 3-4 times
  /// fewer iterations (23 against 77 at 128 x 128, cold); false: Polonsky
  /// and Keer's plain iteration (for comparison; the same solution to the
  /// tolerance).
  bool preconditioned = true;
  NormalContactKeys keys;
};

struct NormalContactSolution {
  Eigen::ArrayXXd pressure_Pa;   ///< nx x ny [Pa]
  double approach_m = 0.0;       ///< delta: the rigid approach of the two bodies [m]
  double carried_force_N = 0.0;  ///< sum(p) dA [N]
  double contact_area_m2 = 0.0;  ///< cells with p > 0 [m^2]
  double plastic_area_m2 = 0.0;  ///< cells at the cap [m^2]
  double max_pressure_Pa = 0.0;
  int max_pressure_i = 0, max_pressure_j = 0;  ///< the cell of the peak
  int iterations = 0;             ///< of the solve that stands (the projected gradient's where it solved)
  bool converged = false;        ///< the tolerance reached within max_iterations
  double complementarity_error = 0.0;  ///< max over contact cells of |g| / (max gap over the grid) [-]
};

/// Solves on `convolution`'s grid (its cell sizes and E*); the problem's
/// fields must have its size. Bad input (a load the grid or the cap cannot
/// carry, a patch reaching the border, a patch under min_cells_across cells,
/// a non-finite gap) throws InputError under the problem's keys; a patch
/// reaching the border, PatchReachesBorder.
NormalContactSolution solve_normal_contact(const NormalContactProblem& problem,
                                           const HalfSpaceConvolution& convolution);

/// The same on a convolution for these cells, built on the first call and
/// kept (one per thread) while the next calls ask for the same grid.
NormalContactSolution solve_normal_contact(const NormalContactProblem& problem, double cell_x_m, double cell_y_m,
                                           double combined_modulus_Pa);

}  // namespace railjoint
