#include "models/normal_contact_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "models/input_error.h"

namespace railjoint {

namespace {

using Mask = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>;

void check_input(const NormalContactProblem& problem, const HalfSpaceConvolution& convolution, const Mask& surface) {
  const NormalContactKeys& keys = problem.keys;
  const Eigen::Index nx = convolution.nx();
  const Eigen::Index ny = convolution.ny();
  if (problem.gap_m.rows() != nx || problem.gap_m.cols() != ny) {
    throw InputError(keys.gap, "the gap field must have the grid's " + std::to_string(nx) + " x " +
                                   std::to_string(ny) + " cells");
  }
  if (!problem.gap_m.isFinite().all()) throw InputError(keys.gap, "the gap field must be finite everywhere");
  if (problem.no_surface.size() != 0 && (problem.no_surface.rows() != nx || problem.no_surface.cols() != ny)) {
    throw InputError(keys.gap, "the no-surface mask must have the gap field's size");
  }
  if (problem.initial_pressure_Pa.size() != 0 &&
      (problem.initial_pressure_Pa.rows() != nx || problem.initial_pressure_Pa.cols() != ny)) {
    throw InputError(keys.gap, "the initial pressure must have the gap field's size");
  }
  if (!std::isfinite(problem.normal_force_N) || !(problem.normal_force_N > 0.0)) {
    throw InputError(keys.load, "the load must be a positive finite force [N]");
  }
  const double cell_area_m2 = convolution.cell_x_m() * convolution.cell_y_m();
  const double surface_area_m2 = cell_area_m2 * static_cast<double>(surface.count());
  if (surface_area_m2 <= 0.0) throw InputError(keys.gap, "the grid has no cell with a surface");
  if (problem.yield_pressure_Pa) {
    const double cap = *problem.yield_pressure_Pa;
    if (!std::isfinite(cap) || !(cap > 0.0)) {
      throw InputError(keys.yield_pressure, "the yield pressure must be a positive finite pressure [Pa]");
    }
    // Even the whole grid at the cap cannot carry the load: no solution exists.
    if (cap * surface_area_m2 <= problem.normal_force_N) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "%.6g Pa over the grid's %.6g m^2 of surface carries at most %.6g N, less than the load %.6g N: "
                    "a higher yield pressure or a lower load",
                    cap, surface_area_m2, cap * surface_area_m2, problem.normal_force_N);
      throw InputError(keys.yield_pressure, text);
    }
  }
}

/// Scales the pressure on `surface` to carry exactly `load`: with a cap,
/// only the cells below it, repeated while the scaling pushes more cells to
/// the cap. Cells at the cap alone over the load (early in the iteration)
/// are scaled down with the rest; cells at the cap alone under it hand the
/// deficit evenly to every cell below the cap, and the iteration takes it
/// off again where the surfaces part. Returns the factor where the whole
/// field was only multiplied by one (the elastic case, and a capped one with
/// no cell at or over the cap), 0 otherwise.
double hold_load(Eigen::ArrayXXd& p, const Mask& surface, double cap, double load, double cell_area) {
  if (std::isinf(cap)) {
    // Elastic: no cell is ever at the cap, the same arithmetic as below.
    const double elastic_force = cell_area * p.sum();
    if (elastic_force > 0.0) {
      const double scale = load / elastic_force;
      p *= scale;
      return scale;
    }
  }
  for (int pass = 0; pass < 1000; ++pass) {
    const Mask plastic = p >= cap;
    const auto plastic_cells = plastic.count();
    const double plastic_force = plastic_cells == 0 ? 0.0 : cap * cell_area * static_cast<double>(plastic_cells);
    const double elastic_force = cell_area * plastic.select(0.0, p).sum();
    if (plastic_force >= load) {
      p *= load / (cell_area * p.sum());
      return 0.0;
    }
    double scale = 0.0;
    if (elastic_force <= 0.0) {
      const Mask below = surface && !plastic;
      p = below.select(p + (load - plastic_force) / (cell_area * static_cast<double>(below.count())), p);
    } else {
      scale = (load - plastic_force) / elastic_force;
      p = plastic.select(p, p * scale);
    }
    if ((p <= cap).all()) return pass == 0 && plastic_cells == 0 ? scale : 0.0;
    p = p.min(cap);  // more cells reached the cap: their excess goes to the rest
  }
  return 0.0;
}

}  // namespace

NormalContactSolution solve_normal_contact(const NormalContactProblem& problem,
                                           const HalfSpaceConvolution& convolution) {
  const int nx = convolution.nx();
  const int ny = convolution.ny();
  const Mask surface = problem.no_surface.size() == 0 ? Mask::Constant(nx, ny, true) : Mask(!problem.no_surface);
  check_input(problem, convolution, surface);
  const double cell_area = convolution.cell_x_m() * convolution.cell_y_m();
  const double load = problem.normal_force_N;
  const double cap = problem.yield_pressure_Pa.value_or(std::numeric_limits<double>::infinity());
  const Eigen::ArrayXXd& h = problem.gap_m;

  // (gap, load) => first guess: the warm start, or the load spread evenly.
  Eigen::ArrayXXd p;
  if (problem.initial_pressure_Pa.size() != 0 && (surface.select(problem.initial_pressure_Pa, 0.0) > 0.0).any()) {
    p = surface.select(problem.initial_pressure_Pa.max(0.0), 0.0);
  } else {
    p = surface.select(Eigen::ArrayXXd::Constant(nx, ny, 1.0), 0.0);
  }
  hold_load(p, surface, cap, load, cell_area);

  // The fields of the iteration, allocated once. Masks enter the sums as
  // 0/1 factors, so that Eigen vectorises each sum.
  Eigen::ArrayXXd t = Eigen::ArrayXXd::Zero(nx, ny);  // conjugate direction, 0 off the active cells
  Eigen::ArrayXXd g(nx, ny);                          // deformed gap less the approach
  Eigen::ArrayXXd u(nx, ny);                          // K p, the elastic approach
  Eigen::ArrayXXd r(nx, ny);                          // K t
  Eigen::ArrayXXd a(nx, ny);                          // 1 on the active cells, 0 elsewhere
  Eigen::ArrayXXd p_old(nx, ny);
  Eigen::ArrayXXd stepped(nx, ny);

  NormalContactSolution solution;
  double g_old = 1.0;
  bool conjugate = false;
  double approach = 0.0;
  // u is K p. A step that only moves p along t and rescales it (no cell
  // clipped at 0 or the cap, none re-entering, hold_load a single factor s)
  // moves u the same way, u <- s (u - tau K t), by linearity: then the next
  // iteration needs one convolution (K t) instead of two. Any other step
  // recomputes u = K p, so u differs from K p only by the FFT's rounding
  // (some 1e-16 relative) summed over the clean steps since.
  bool u_is_K_p = false;
  for (int iteration = 1; iteration <= problem.max_iterations; ++iteration) {
    solution.iterations = iteration;
    if (!u_is_K_p) convolution.deflection_m(p, u);
    // (p) => g: the gap with the elastic approach, less its mean over the
    // elastic contact cells (there the deformed gap is zero: the mean is delta).
    g = h + u;
    a = (surface && p > 0.0 && p < cap).cast<double>();
    double n_active = a.sum();
    if (n_active == 0.0) {
      a = (surface && p > 0.0).cast<double>();
      n_active = a.sum();
    }
    approach = (a * g).sum() / n_active;
    g -= approach;
    const double g_norm = (a * g.square()).sum();
    // (g, t) => t: the conjugate direction on the active cells.
    const double beta = conjugate ? g_norm / g_old : 0.0;
    t = a * (g + beta * t);
    g_old = g_norm;
    // (t) => tau: the step that minimises the energy along t; r less its
    // mean over the active cells (t is 0 elsewhere).
    convolution.deflection_m(t, r);
    const double r_mean = (a * r).sum() / n_active;
    const double rt = ((r - r_mean) * t).sum();
    const double tau = rt > 0.0 ? (g * t).sum() / rt : 0.0;
    // (p, tau, t) => p: the step, then the bounds 0 <= p <= cap; cells that
    // overlap without pressure (or sit at the cap and open) re-enter, and
    // the conjugacy restarts.
    p_old = p;
    stepped = p - tau * t;
    p = stepped.max(0.0).min(cap);
    const bool clipped = (p != stepped).any();
    const Mask reentering = surface && ((p <= 0.0 && g < 0.0) || (p >= cap && g > 0.0));
    conjugate = !reentering.any();
    if (!conjugate) p = reentering.select((p - tau * g).max(0.0).min(cap), p);
    if (problem.no_surface.size() != 0) p = surface.select(p, 0.0);
    // (p) => p: the load held exactly.
    const double scale = hold_load(p, surface, cap, load, cell_area);
    u_is_K_p = !clipped && conjugate && scale > 0.0;
    if (u_is_K_p) u = scale * (u - tau * r);
    const double change = (p - p_old).abs().sum() / p.sum();
    if (!std::isfinite(change)) throw std::runtime_error("solve_normal_contact: the iteration diverged (a non-finite pressure)");
    if (change < problem.tolerance) {
      solution.converged = true;
      break;
    }
  }

  // The result and what it can vouch for.
  solution.pressure_Pa = p;
  solution.approach_m = approach;
  solution.carried_force_N = cell_area * p.sum();
  solution.contact_area_m2 = cell_area * static_cast<double>((p > 0.0).count());
  solution.plastic_area_m2 = std::isfinite(cap) ? cell_area * static_cast<double>((p >= cap).count()) : 0.0;
  Eigen::Index max_i = 0, max_j = 0;
  solution.max_pressure_Pa = p.maxCoeff(&max_i, &max_j);
  solution.max_pressure_i = static_cast<int>(max_i);
  solution.max_pressure_j = static_cast<int>(max_j);
  const Mask elastic_contact = p > 0.0 && p < cap;
  const double gap_scale = std::max(h.abs().maxCoeff(), std::numeric_limits<double>::min());
  solution.complementarity_error = elastic_contact.any() ? elastic_contact.select(g.abs(), 0.0).maxCoeff() / gap_scale : 0.0;

  // A patch touching the border would have spread further on a larger grid.
  const Mask in_contact = p > 0.0;
  if (in_contact.row(0).any() || in_contact.row(nx - 1).any() || in_contact.col(0).any() ||
      in_contact.col(ny - 1).any()) {
    // Under a cap with cells at it, the cap spread the patch: blame the cap.
    const bool capped = solution.plastic_area_m2 > 0.0;
    throw InputError(capped ? problem.keys.yield_pressure : problem.keys.load,
                     std::string("the contact patch reaches the grid's border: the grid cannot carry this load") +
                         (capped ? " at this cap; a higher yield pressure, " : "; ") +
                         "a larger grid (more cells or larger cells) or a smaller load");
  }
  int first_i = nx, last_i = -1, first_j = ny, last_j = -1;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (!in_contact(i, j)) continue;
      first_i = std::min(first_i, i);
      last_i = std::max(last_i, i);
      first_j = std::min(first_j, j);
      last_j = std::max(last_j, j);
    }
  }
  const int across = std::min(last_i - first_i + 1, last_j - first_j + 1);
  if (across < problem.min_cells_across) {
    throw InputError(problem.keys.grid, "the contact patch spans only " + std::to_string(across) +
                                            " cells across (at least " + std::to_string(problem.min_cells_across) +
                                            " needed): smaller cells");
  }
  return solution;
}

NormalContactSolution solve_normal_contact(const NormalContactProblem& problem, double cell_x_m, double cell_y_m,
                                           double combined_modulus) {
  if (!(cell_x_m > 0.0) || !(cell_y_m > 0.0) || !std::isfinite(cell_x_m) || !std::isfinite(cell_y_m)) {
    throw InputError(problem.keys.grid, "the cell sizes must be positive and finite [m]");
  }
  if (problem.gap_m.rows() < 2 || problem.gap_m.cols() < 2) {
    throw InputError(problem.keys.gap, "the gap field needs at least 2 x 2 cells");
  }
  const HalfSpaceConvolution convolution(static_cast<int>(problem.gap_m.rows()), static_cast<int>(problem.gap_m.cols()),
                                         cell_x_m, cell_y_m, combined_modulus);
  return solve_normal_contact(problem, convolution);
}

}  // namespace railjoint
