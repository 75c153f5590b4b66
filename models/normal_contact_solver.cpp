#include "models/normal_contact_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "support/input_error.h"

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

// Cells around the contact on which K t is computed too: the patch can grow
// by this much in one step and still be tested for overlap.
constexpr int kBoxMargin = 2;

// Preconditioned iterations before a solve that has not converged goes on
// without the preconditioner (from where it stands, so nothing is lost but
// these): a safety net, never reached by the tests and benchmarks (at most
// 29 iterations cold up to 512 x 512, 41 on the random scenes of
// NormalContactPreconditioner).
constexpr int kPreconditionedIterations = 200;

// Iterations after a cell first reaches the cap before Polonsky and Keer's
// iteration is given up for solve_projected: where it converges under a cap
// it takes at most 66 in all (316 capped steps of seeded random crossings,
// 2026-11-29); where it does not, it cycles, and more never help.
constexpr int kCappedIterations = 300;

// solve_projected's stopping test, relative to the problem's tolerance.
constexpr double kProjectedTolerance = 1e-2;

/// A sum over the cells in four lanes (cell n in lane n mod 4): four
/// independent chains of additions instead of one.
struct Lanes {
  double lane[4] = {0.0, 0.0, 0.0, 0.0};
  void add(int k, double value) { lane[k] += value; }
  double total() const { return (lane[0] + lane[1]) + (lane[2] + lane[3]); }
};

/// body(n, k) for every cell n, k = n mod 4 a constant once inlined, so
/// that each lane's sum stays in a register.
template <class Body>
inline void for_each_cell(Eigen::Index cells, Body&& body) {
  Eigen::Index n = 0;
  for (; n + 4 <= cells; n += 4) {
    body(n, 0);
    body(n + 1, 1);
    body(n + 2, 2);
    body(n + 3, 3);
  }
  for (; n < cells; ++n) body(n, static_cast<int>(n & 3));
}

}  // namespace

namespace {

/// The cells with a surface, the problem checked on them.
Mask checked_surface(const NormalContactProblem& problem, const HalfSpaceConvolution& convolution) {
  const Mask surface = problem.no_surface.size() == 0 ? Mask::Constant(convolution.nx(), convolution.ny(), true)
                                                      : Mask(!problem.no_surface);
  check_input(problem, convolution, surface);
  return surface;
}

/// A solve's start before the load is put on it: the warm start where it
/// presses on a surface cell, else 1 on every surface cell (the load spread
/// evenly).
Eigen::ArrayXXd start_field(const NormalContactProblem& problem, const Mask& surface) {
  if (problem.initial_pressure_Pa.size() != 0 && (surface.select(problem.initial_pressure_Pa, 0.0) > 0.0).any()) {
    return surface.select(problem.initial_pressure_Pa.max(0.0), 0.0);
  }
  return surface.select(Eigen::ArrayXXd::Constant(surface.rows(), surface.cols(), 1.0), 0.0);
}

/// (p, g, delta) => the solution.
NormalContactSolution describe(const NormalContactProblem& problem, const Eigen::ArrayXXd& p, const Eigen::ArrayXXd& g,
                               double approach, int iterations, bool converged, double cell_area) {
  const double cap = problem.yield_pressure_Pa.value_or(std::numeric_limits<double>::infinity());
  const Eigen::ArrayXXd& h = problem.gap_m;
  NormalContactSolution solution;
  solution.iterations = iterations;
  solution.converged = converged;
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
  return solution;
}

/// What a solution cannot vouch for, refused (InputError): a patch reaching
/// the grid's border, or one spanning too few cells.
void refuse_unusable_patch(const NormalContactProblem& problem, const NormalContactSolution& solution) {
  const Eigen::ArrayXXd& p = solution.pressure_Pa;
  const int nx = static_cast<int>(p.rows());
  const int ny = static_cast<int>(p.cols());
  // A patch touching the border would have spread further on a larger grid.
  const Mask in_contact = p > 0.0;
  if (in_contact.row(0).any() || in_contact.row(nx - 1).any() || in_contact.col(0).any() ||
      in_contact.col(ny - 1).any()) {
    // Under a cap with cells at it, the cap spread the patch: blame the cap.
    const bool capped = solution.plastic_area_m2 > 0.0;
    throw PatchReachesBorder(capped ? problem.keys.yield_pressure : problem.keys.load,
                             std::string("the contact patch reaches the grid's border: the grid cannot carry this "
                                         "load") +
                                 (capped ? " at this cap; a higher yield pressure, " : "; ") + "a larger grid (" +
                                 problem.keys.larger_grid + ") or a smaller load");
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
}

/// (q) => p: the nearest field to q (least squares) with 0 <= p <= cap on
/// `surface`, 0 elsewhere, and sum(p) = total: p = clip(q - mu, 0, cap), mu
/// the root of the sum, which falls as mu grows (piecewise linear: Newton's
/// steps kept inside a bracket that halves where they leave it).
void project_on_load(const Eigen::ArrayXXd& q, const Mask& surface, double cap, double total, Eigen::ArrayXXd& p) {
  const auto carried = [&](double mu, double& slope) {
    double sum = 0.0;
    double free_cells = 0.0;
    for (Eigen::Index n = 0; n < q.size(); ++n) {
      if (!surface(n)) continue;
      const double pn = q(n) - mu;
      if (pn >= cap) {
        sum += cap;
      } else if (pn > 0.0) {
        sum += pn;
        free_cells += 1.0;
      }
    }
    slope = free_cells;
    return sum;
  };
  double q_min = std::numeric_limits<double>::infinity(), q_max = -q_min;
  for (Eigen::Index n = 0; n < q.size(); ++n) {
    if (!surface(n)) continue;
    q_min = std::min(q_min, q(n));
    q_max = std::max(q_max, q(n));
  }
  // At mu = q_min - cap every surface cell is at the cap (more than the
  // load: check_input), at mu = q_max none carries anything.
  double lo = q_min - cap, hi = q_max, mu = 0.5 * (lo + hi);
  for (int k = 0; k < 200 && hi - lo > 1e-15 * std::max(std::abs(lo), std::abs(hi)); ++k) {
    double slope = 0.0;
    const double excess = carried(mu, slope) - total;
    if (std::abs(excess) <= 1e-15 * total) break;  // rounding: Newton has found the linear piece
    (excess > 0.0 ? lo : hi) = mu;
    const double newton = slope > 0.0 ? mu + excess / slope : 0.5 * (lo + hi);
    mu = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
  }
  p = surface.select((q - mu).max(0.0).min(cap), 0.0);
}

/// The capped problem as the convex quadratic programme it is:
///   min 1/2 p.K p + p.h  s.t.  0 <= p <= cap, sum(p) dA = W,
/// K symmetric positive definite, so one minimum, whose optimality
/// conditions are the contact's (g = h + K p - delta >= 0 where p = 0, = 0
/// where 0 < p < cap, <= 0 at the cap; delta the load's multiplier).
/// Solved by the accelerated projected gradient (Beck and Teboulle's FISTA,
/// SIAM J. Imaging Sci. 2, 2009) with O'Donoghue and Candes's restart
/// (Found. Comput. Math. 15, 2015): each step the gradient h + K y at step
/// 1/L (L >= K's largest eigenvalue), then project_on_load. It converges
/// from any start: the fallback where Polonsky and Keer's iteration, whose
/// load scaling is no projection once cells are capped, cycles.
NormalContactSolution solve_projected(const NormalContactProblem& problem, const HalfSpaceConvolution& convolution) {
  const Mask surface = checked_surface(problem, convolution);
  const double cell_area = convolution.cell_x_m() * convolution.cell_y_m();
  const double cap = problem.yield_pressure_Pa.value_or(std::numeric_limits<double>::infinity());
  const double total = problem.normal_force_N / cell_area;
  const Eigen::ArrayXXd& h = problem.gap_m;
  // K's entries are all positive: its largest row sum (K 1's largest entry)
  // bounds its largest eigenvalue (Gershgorin).
  const Eigen::ArrayXXd ones = surface.select(Eigen::ArrayXXd::Constant(surface.rows(), surface.cols(), 1.0), 0.0);
  const double step = 1.0 / convolution.deflection_m(ones).maxCoeff();
  Eigen::ArrayXXd p, p_next, y, u;
  project_on_load(start_field(problem, surface), surface, cap, total, p);
  y = p;
  double momentum = 1.0;
  int iteration = 0;
  bool converged = false;
  while (iteration < problem.max_iterations && !converged) {
    ++iteration;
    // (y) => p_next: a projected gradient step.
    convolution.deflection_m(y, u);
    project_on_load(y - step * (h + u), surface, cap, total, p_next);
    // The step's length from y (the gradient mapping) vanishes at the minimum
    // only; at step 1/L it is short, and stopping at a hundredth of the
    // tolerance puts the field as near Polonsky and Keer's as their warm and
    // even starts are to each other (sum |dp| dA 2e-5 N against 1e-5 N, at
    // the tolerance 2e-3 N, on a 120-250 kN crossing of 96 x 72 cells).
    converged = (p_next - y).abs().sum() / p_next.sum() < kProjectedTolerance * problem.tolerance;
    // Restart where the step turns against the momentum.
    const bool restart = ((y - p_next) * (p_next - p)).sum() > 0.0;
    const double momentum_next = restart ? 1.0 : 0.5 * (1.0 + std::sqrt(1.0 + 4.0 * momentum * momentum));
    y = restart ? p_next : Eigen::ArrayXXd(p_next + (momentum - 1.0) / momentum_next * (p_next - p));
    momentum = momentum_next;
    p.swap(p_next);
  }
  // (p) => g, delta: delta the mean of h + K p over the cells strictly
  // between the bounds (all the cells in contact where none is).
  convolution.deflection_m(p, u);
  Eigen::ArrayXXd g = h + u;
  Mask between = surface && p > 0.0 && p < cap;
  if (!between.any()) between = surface && p > 0.0;
  const double approach = between.select(g, 0.0).sum() / static_cast<double>(between.count());
  g -= approach;
  return describe(problem, p, g, approach, iteration, converged, cell_area);
}

// One solve from the problem's start (its warm start, or the load spread
// evenly).
NormalContactSolution solve_from_start(const NormalContactProblem& problem, const HalfSpaceConvolution& convolution) {
  const int nx = convolution.nx();
  const int ny = convolution.ny();
  const Mask surface = checked_surface(problem, convolution);
  const double cell_area = convolution.cell_x_m() * convolution.cell_y_m();
  const double load = problem.normal_force_N;
  const double cap = problem.yield_pressure_Pa.value_or(std::numeric_limits<double>::infinity());
  const Eigen::ArrayXXd& h = problem.gap_m;

  // (gap, load) => first guess: the warm start, or the load spread evenly.
  Eigen::ArrayXXd p = start_field(problem, surface);
  hold_load(p, surface, cap, load, cell_area);

  // The fields of the iteration, allocated once, walked by index in a few
  // fused passes (each pass reads and writes several fields per cell).
  const Eigen::Index cells = static_cast<Eigen::Index>(nx) * ny;
  Eigen::ArrayXXd t = Eigen::ArrayXXd::Zero(nx, ny);  // conjugate direction, 0 off the active cells
  Eigen::ArrayXXd g(nx, ny);                          // deformed gap less the approach
  Eigen::ArrayXXd u = Eigen::ArrayXXd::Zero(nx, ny);  // K p, the elastic approach (finite off the box: see r)
  Eigen::ArrayXXd r = Eigen::ArrayXXd::Zero(nx, ny);  // K t (finite everywhere: off the box it enters sums times 0)
  Eigen::ArrayXXd a(nx, ny);                          // 1 on the active cells, 0 elsewhere
  Eigen::ArrayXXd p_old(nx, ny);
  Eigen::ArrayXXd stepped(nx, ny);
  Eigen::ArrayXXd z = Eigen::ArrayXXd::Zero(nx, ny);  // the preconditioned gap, 0 off the active cells
  // The cells a step moved off the line p - tau t (clipped at a bound or
  // re-entering) and by how much: K of that is added by direct sum when
  // they are few (cheaper than a product).
  const std::size_t direct_cells = static_cast<std::size_t>(convolution.direct_cells_per_product());
  std::vector<Eigen::Index> moved_cells;
  std::vector<double> moved_by_Pa;
  moved_cells.reserve(direct_cells);
  moved_by_Pa.reserve(direct_cells);
  const bool* on = surface.data();
  const double* hd = h.data();
  double *pd = p.data(), *td = t.data(), *gd = g.data(), *ud = u.data(), *rd = r.data(), *ad = a.data(),
         *p_oldd = p_old.data(), *zd = z.data();

  NormalContactSolution solution;
  double g_old = 1.0;
  bool conjugate = false;
  bool preconditioned_last = false;
  bool reached_cap = false;
  int reached_cap_at = 0;
  double approach = 0.0;
  // u is K p. A step moves p along t, moves some cells off that line (the
  // bounds, re-entry), then scales it (hold_load). Where the scaling is a
  // single factor s and the moved cells are few, u follows by linearity:
  // u <- s (u - tau K t + K d), d the moved cells' offsets, K d by direct
  // sum; then an iteration needs one product (K t) instead of two. Any other
  // step recomputes u = K p, so u differs from K p only by rounding (some
  // 1e-16 relative) summed over the steps since.
  bool u_is_K_p = false;
  // K t is needed on the contact's cells only (t vanishes off them): on a
  // box around the contact it is a product on the box's own, smaller,
  // padded grid. u then follows on the box alone, and where it is
  // recomputed it is recomputed there (p vanishes off the box too): `exact`
  // is where u is K p; the overlap test skips the cells outside it, and a
  // solve that converged on a box checks them once with a whole product
  // (tests/models/normal_contact_solver_test.cpp, NormalContactOverlap).
  using Box = HalfSpaceConvolution::CellBox;
  const Box whole{0, 0, nx, ny};
  const auto is_whole = [&](const Box& b) { return b.cells_x == nx && b.cells_y == ny; };
  const auto within = [](const Box& b, const Box& in) {
    return b.first_i >= in.first_i && b.first_j >= in.first_j && b.first_i + b.cells_x <= in.first_i + in.cells_x &&
           b.first_j + b.cells_y <= in.first_j + in.cells_y;
  };
  Box exact = whole;
  for (int iteration = 1; iteration <= problem.max_iterations; ++iteration) {
    solution.iterations = iteration;
    // (p) => box: the contact's cells and kBoxMargin more on each side, where
    // the patch may grow in one step with u known.
    int first_i = nx, last_i = -1, first_j = ny, last_j = -1;
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        if (!(p(i, j) > 0.0)) continue;
        first_i = std::min(first_i, i);
        last_i = std::max(last_i, i);
        first_j = std::min(first_j, j);
        last_j = std::max(last_j, j);
      }
    }
    const std::optional<Box> box =
        last_i < 0 ? std::nullopt
                   : convolution.product_box(std::max(0, first_i - kBoxMargin), std::min(nx - 1, last_i + kBoxMargin),
                                             std::max(0, first_j - kBoxMargin), std::min(ny - 1, last_j + kBoxMargin));
    // (p) => u = K p where it is not known on the box: p vanishes off the
    // box, so the box's own product gives it there.
    if (!u_is_K_p || (box && !within(*box, exact))) {
      if (box) {
        convolution.box_deflection_m(p, *box, u);
        exact = *box;
      } else {
        convolution.deflection_m(p, u);
        exact = whole;
      }
    }
    // (p, u) => g, a: the gap with the elastic approach, less its mean over
    // the elastic contact cells (there the deformed gap is zero: the mean is delta).
    // Sums in four lanes, so that the additions do not wait on each other.
    Lanes n_active, g_sum, n_plastic;
    for_each_cell(cells, [&](Eigen::Index n, int k) {
      const double gn = hd[n] + ud[n];
      const double an = static_cast<double>(on[n] & (pd[n] > 0.0) & (pd[n] < cap));
      gd[n] = gn;
      ad[n] = an;
      n_active.add(k, an);
      g_sum.add(k, an * gn);
      n_plastic.add(k, static_cast<double>(pd[n] >= cap));
    });
    if (n_active.total() == 0.0) {  // every cell in contact at the cap: the contact cells act
      n_active = Lanes();
      g_sum = Lanes();
      for_each_cell(cells, [&](Eigen::Index n, int k) {
        const double an = static_cast<double>(on[n] & (pd[n] > 0.0));
        ad[n] = an;
        n_active.add(k, an);
        g_sum.add(k, an * gd[n]);
      });
    }
    const double active_cells = n_active.total();
    approach = g_sum.total() / active_cells;
    Lanes g_norm;
    for_each_cell(cells, [&](Eigen::Index n, int k) {
      const double gn = gd[n] - approach;
      gd[n] = gn;
      g_norm.add(k, ad[n] * gn * gn);
    });
    // (g) => z: the preconditioned gap on the active cells, less its mean
    // there (a direction of zero sum keeps the load), and g.z in place of
    // g.g. Not once a cell has reached the cap: there the preconditioned
    // step was seen to cycle (a thin elastic ring between the plastic core
    // and the edge; cells leaving and re-entering the cap). The plain one
    // can cycle too (solve_projected), less often.
    reached_cap = reached_cap || n_plastic.total() > 0.0;
    if (reached_cap && reached_cap_at == 0) reached_cap_at = iteration;
    if (reached_cap && iteration - reached_cap_at >= kCappedIterations) break;  // not converged
    const bool precondition = problem.preconditioned && !reached_cap && iteration <= kPreconditionedIterations;
    if (precondition != preconditioned_last) conjugate = false;  // another metric: the conjugacy restarts
    preconditioned_last = precondition;
    double g_z = g_norm.total();
    if (precondition) {
      for_each_cell(cells, [&](Eigen::Index n, int) { zd[n] = ad[n] * gd[n]; });
      if (box) {
        convolution.box_approximate_pressure_Pa(z, *box, z);
      } else {
        convolution.approximate_pressure_Pa(z, z);
      }
      Lanes z_sum;
      for_each_cell(cells, [&](Eigen::Index n, int k) { z_sum.add(k, ad[n] * zd[n]); });
      const double z_mean = z_sum.total() / active_cells;
      Lanes gz;
      for_each_cell(cells, [&](Eigen::Index n, int k) {
        const double zn = ad[n] * (zd[n] - z_mean);
        zd[n] = zn;
        gz.add(k, gd[n] * zn);
      });
      g_z = gz.total();
    }
    // (g or z, t) => t: the conjugate direction on the active cells.
    const double beta = conjugate ? g_z / g_old : 0.0;
    g_old = g_z;
    const double* direction = precondition ? zd : gd;
    Lanes gt;
    for_each_cell(cells, [&](Eigen::Index n, int k) {
      const double tn = ad[n] * (direction[n] + beta * td[n]);
      td[n] = tn;
      gt.add(k, gd[n] * tn);
    });
    // (t) => tau: the step that minimises the energy along t, with r less its
    // mean over the active cells: sum (r - r_mean) t = sum r t - r_mean sum t
    // (t is 0 off the active cells).
    if (box) {
      convolution.box_deflection_m(t, *box, r);
    } else {
      convolution.deflection_m(t, r);
    }
    Lanes ar, rt, t_sum;
    for_each_cell(cells, [&](Eigen::Index n, int k) {
      ar.add(k, ad[n] * rd[n]);
      rt.add(k, rd[n] * td[n]);
      t_sum.add(k, td[n]);
    });
    const double energy = rt.total() - ar.total() / active_cells * t_sum.total();
    const double tau = energy > 0.0 ? gt.total() / energy : 0.0;
    // (p, tau, t) => p: the step, then the bounds 0 <= p <= cap; cells that
    // overlap without pressure (or sit at the cap and open) re-enter, and
    // the conjugacy restarts. Whole-field operations here (vectorised, no
    // branch on data that changes from cell to cell).
    p_old = p;
    stepped = p - tau * t;
    p = stepped.max(0.0).min(cap);
    const bool clipped = (p != stepped).any();
    Mask reentering = surface && ((p <= 0.0 && g < 0.0) || (p >= cap && g > 0.0));
    if (!is_whole(exact)) {  // g is known on `exact` only
      reentering.topRows(exact.first_i).setConstant(false);
      reentering.bottomRows(nx - exact.first_i - exact.cells_x).setConstant(false);
      reentering.leftCols(exact.first_j).setConstant(false);
      reentering.rightCols(ny - exact.first_j - exact.cells_y).setConstant(false);
    }
    conjugate = !reentering.any();
    // A re-entering cell steps along its own gap: tau has the units of
    // 1 / K's where t is a gap, of 1 / (K M) where t is a pressure (the
    // preconditioned), and M's diagonal turns the gap into a pressure.
    const double reentry_scale = precondition ? convolution.preconditioner_diagonal_Pa_per_m() : 1.0;
    if (!conjugate) p = reentering.select((p - tau * reentry_scale * g).max(0.0).min(cap), p);
    if (problem.no_surface.size() != 0) p = surface.select(p, 0.0);
    // (p, stepped) => d: the moved cells, while they are few.
    bool few_moved = true;
    moved_cells.clear();
    moved_by_Pa.clear();
    if (clipped || !conjugate) {
      for (Eigen::Index n = 0; n < cells && few_moved; ++n) {
        if (pd[n] == stepped(n)) continue;
        few_moved = moved_cells.size() < direct_cells;
        moved_cells.push_back(n);
        moved_by_Pa.push_back(pd[n] - stepped(n));
      }
    }
    // (p) => p: the load held exactly.
    const double scale = hold_load(p, surface, cap, load, cell_area);
    u_is_K_p = few_moved && scale > 0.0;
    if (u_is_K_p) {
      if (box) exact = *box;  // r is K t there only
      u -= tau * r;
      if (!moved_cells.empty()) convolution.add_cell_deflections_m(moved_cells, moved_by_Pa, u);
      u *= scale;
    }
    Lanes change_sum, p_sum;
    for_each_cell(cells, [&](Eigen::Index n, int k) {
      change_sum.add(k, std::abs(pd[n] - p_oldd[n]));
      p_sum.add(k, pd[n]);
    });
    const double change = change_sum.total() / p_sum.total();
    if (!std::isfinite(change)) throw std::runtime_error("solve_normal_contact: the iteration diverged (a non-finite pressure)");
    if (change < problem.tolerance) {
      // Under the cap the step can stall on a point that is no solution:
      // with one cell between the bounds there is no direction (tau = 0)
      // and the cells on the wrong side of a bound, which step by tau too,
      // stay there. Given up for solve_projected.
      if (reached_cap && !conjugate) break;
      if (!is_whole(exact)) {
        // Converged on the box: the cells outside it must not overlap.
        convolution.deflection_m(p, u);
        exact = whole;
        u_is_K_p = true;
        if ((surface && p <= 0.0 && h + u - approach < 0.0).any()) continue;
      }
      solution.converged = true;
      break;
    }
  }

  return describe(problem, p, g, approach, solution.iterations, solution.converged, cell_area);
}

}  // namespace

NormalContactSolution solve_normal_contact(const NormalContactProblem& problem,
                                           const HalfSpaceConvolution& convolution) {
  // Under the cap Polonsky and Keer's iteration can cycle (its load held by
  // scaling, which there is no projection: the capped set empties, the
  // deficit spreads over the grid; docs/rail-end-contact.md, "Where neither
  // start converged"), more often from a warm start under another load. A
  // solve that does not converge is solved again from the even start, and a
  // capped one that still does not, by solve_projected, which converges from
  // any start. Only the answer that stands is judged for its patch: a field
  // that has not converged may spread to the border, and a converged one
  // refused there is the problem's one solution, refused at once.
  const auto judged = [&problem](NormalContactSolution solution) {
    refuse_unusable_patch(problem, solution);
    return solution;
  };
  NormalContactProblem even;
  const NormalContactProblem* from_even = &problem;
  if (problem.initial_pressure_Pa.size() != 0) {
    NormalContactSolution warm = solve_from_start(problem, convolution);
    if (warm.converged) return judged(std::move(warm));
    even = problem;
    even.initial_pressure_Pa.resize(0, 0);
    from_even = &even;
  }
  NormalContactSolution cold = solve_from_start(*from_even, convolution);
  if (cold.converged || !problem.yield_pressure_Pa) return judged(std::move(cold));
  return judged(solve_projected(problem, convolution));
}

NormalContactSolution solve_normal_contact(const NormalContactProblem& problem, double cell_x_m, double cell_y_m,
                                           double combined_modulus) {
  if (!(cell_x_m > 0.0) || !(cell_y_m > 0.0) || !std::isfinite(cell_x_m) || !std::isfinite(cell_y_m)) {
    throw InputError(problem.keys.grid, "the cell sizes must be positive and finite [m]");
  }
  if (problem.gap_m.rows() < 2 || problem.gap_m.cols() < 2) {
    throw InputError(problem.keys.gap, "the gap field needs at least 2 x 2 cells");
  }
  // The last grid's convolution (plans, influence coefficients and their
  // transform) is kept per thread: repeated solves on one grid (Python
  // loops, tests) build it once.
  thread_local std::unique_ptr<HalfSpaceConvolution> last;
  const int nx = static_cast<int>(problem.gap_m.rows());
  const int ny = static_cast<int>(problem.gap_m.cols());
  if (!last || last->nx() != nx || last->ny() != ny || last->cell_x_m() != cell_x_m || last->cell_y_m() != cell_y_m ||
      last->combined_modulus_Pa() != combined_modulus) {
    last.reset();  // its buffers freed before the next one's are taken
    last = std::make_unique<HalfSpaceConvolution>(nx, ny, cell_x_m, cell_y_m, combined_modulus);
  }
  return solve_normal_contact(problem, *last);
}

}  // namespace railjoint
