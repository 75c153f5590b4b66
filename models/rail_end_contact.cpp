#include "models/rail_end_contact.h"
#include "models/rail_end_fields.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "models/contact_curvatures.h"
#include "models/half_space_convolution.h"
#include "models/half_space_influence.h"
#include "models/hertz_contact.h"
#include "models/normal_contact_solver.h"
#include "models/rail_end_edge_load.h"
#include "models/rail_head.h"
#include "models/rail_top.h"
#include "models/wheel_tread.h"
#include "support/input_error.h"

namespace railjoint {

namespace {

// A wheel of width b_w has its tread over y_w +- b_w / 2; a thin disc (b_w =
// 0), whose contact is a line, is taken as a tread across the whole head, as
// the thesis's local model takes the wheel (a Hertz patch on the crown).
bool on_tread(const WheelParams& wheel, double y_m) {
  return wheel.width_m == 0.0 || std::abs(y_m - wheel.lateral_m) <= 0.5 * wheel.width_m;
}

// Height of the wheel's slice at y below its centre, at dx from the centre
// plane; off the tread, no wheel (infinite: no contact there).
double wheel_bottom_m(const WheelParams& wheel, double dx_m, double y_m) {
  if (!on_tread(wheel, y_m)) return std::numeric_limits<double>::infinity();
  const double r = tread_radius_m(wheel, y_m);
  return -std::sqrt(r * r - dx_m * dx_m);
}

double rail_height_m(const JointParams& joint, const RailEndContactSettings& settings, double x_m, double y_m) {
  const double z = rail_top_height_m(joint, x_m, y_m);
  return x_m >= cut_x_m(joint, y_m, 1) ? z + settings.height_mismatch_m : z;
}

// The lateral line of first contact: where the tread comes closest to the
// head, over the part of the head the tread covers.
double contact_y_m(const JointParams& joint, const WheelParams& wheel) {
  double lo = -joint.half_width_m, hi = joint.half_width_m;
  if (wheel.width_m > 0.0) {
    lo = std::max(lo, wheel.lateral_m - 0.5 * wheel.width_m);
    hi = std::min(hi, wheel.lateral_m + 0.5 * wheel.width_m);
    if (!(lo <= hi)) {
      throw InputError("wheel.y", "the tread (wheel.width wide about wheel.y) does not reach the rail head "
                                  "(joint.half_width either side of its centre line)");
    }
  }
  const int samples = 4001;
  double best_y = lo;
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < samples; ++k) {
    const double y = lo + (hi - lo) * k / (samples - 1);
    const double gap = -tread_radius_m(wheel, y) - head_top_height_m(joint, y);
    // Ties (a cylinder on a flat head) go to the wheel's own plane.
    if (gap < best - 1e-15 || (std::abs(gap - best) <= 1e-15 && std::abs(y - wheel.lateral_m) < std::abs(best_y - wheel.lateral_m))) {
      best = gap;
      best_y = y;
    }
  }
  return best_y;
}

// Along the contact line, where the wheel at x_wheel first touches a rail.
double contact_x_m(const JointParams& joint, const WheelParams& wheel, const RailEndContactSettings& settings,
                   double x_wheel_m, double y_m) {
  const int samples = 1201;
  const double reach = 0.03;
  double best_x = x_wheel_m;
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < samples; ++k) {
    const double x = x_wheel_m - reach + 2.0 * reach * k / (samples - 1);
    const double gap = wheel_bottom_m(wheel, x - x_wheel_m, y_m) - rail_height_m(joint, settings, x, y_m);
    if (std::isfinite(gap) && gap < best) {
      best = gap;
      best_x = x;
    }
  }
  return best_x;
}

// A cell in contact whose neighbour along x or y has no surface, or lies on
// the other rail end where the ends are at different heights (a step even
// without a gap, as is the dip's at y != 0 on an inclined cut; a closed gap
// without either is one continuous surface).
bool contact_at_edge(const RailEndGap& gap, const Eigen::ArrayXXd& pressure_Pa, bool ends_differ) {
  const Eigen::Index nx = pressure_Pa.rows(), ny = pressure_Pa.cols();
  const auto edge = [&](Eigen::Index i, Eigen::Index j, Eigen::Index k, Eigen::Index l) {
    if (k < 0 || l < 0 || k >= nx || l >= ny) return false;
    return gap.no_surface(k, l) || (ends_differ && gap.incoming(k, l) != gap.incoming(i, j));
  };
  for (Eigen::Index j = 0; j < ny; ++j) {
    for (Eigen::Index i = 0; i < nx; ++i) {
      if (!(pressure_Pa(i, j) > 0.0)) continue;
      if (edge(i, j, i - 1, j) || edge(i, j, i + 1, j) || edge(i, j, i, j - 1) || edge(i, j, i, j + 1)) return true;
    }
  }
  return false;
}

// A cell in contact beside a cell without surface that is not the end-post
// gap's: the head's side or the tread's rim, where the edge pressure (taken
// at the cuts) does not look.
bool contact_at_side(const JointParams& joint, const RailEndGap& gap, const Eigen::ArrayXXd& pressure_Pa) {
  const Eigen::Index nx = pressure_Pa.rows(), ny = pressure_Pa.cols();
  const auto side = [&](Eigen::Index k, Eigen::Index l) {
    if (k < 0 || l < 0 || k >= nx || l >= ny || !gap.no_surface(k, l)) return false;
    const double x = gap.x0_m + static_cast<double>(k) * gap.dx_m, y = gap.y0_m + static_cast<double>(l) * gap.dy_m;
    return !(std::abs(y) <= joint.half_width_m && x > cut_x_m(joint, y, 0) && x < cut_x_m(joint, y, 1));
  };
  for (Eigen::Index j = 0; j < ny; ++j) {
    for (Eigen::Index i = 0; i < nx; ++i) {
      if (pressure_Pa(i, j) > 0.0 && (side(i - 1, j) || side(i + 1, j) || side(i, j - 1) || side(i, j + 1))) return true;
    }
  }
  return false;
}

bool ties(double a, double b) { return std::abs(a - b) <= kPeakTie * std::max(std::abs(a), std::abs(b)); }

// (the peak step) => its edge pressure at half the cells' size on the same
// window (crossing.peak_gap's), started from its coarse field (each cell's
// pressure on its four).
EdgePressureGridCheck check_edge_grid(const JointParams& joint, const WheelParams& wheel,
                                      const RailEndContactSettings& settings, const RailEndCrossing& crossing,
                                      double E_star, const NormalContactKeys& keys) {
  RailEndContactSettings fine = settings;
  fine.cells_x *= 2;
  fine.cells_y *= 2;
  const RailEndGap& coarse = crossing.peak_gap;
  const RailEndStep& step = crossing.steps[crossing.peak_step];
  const double dx = 0.5 * coarse.dx_m, dy = 0.5 * coarse.dy_m;
  // The fine cells tile the coarse window: the first's centre a quarter of a coarse cell in from the coarse one's.
  const double x_centre = coarse.x0_m - 0.5 * dx + settings.cells_x * dx;
  const double y_centre = coarse.y0_m - 0.5 * dy + settings.cells_y * dy;
  const RailEndGap gap = rail_end_gap(joint, wheel, fine, step.x_wheel_m, x_centre, y_centre, dx, dy);
  NormalContactProblem problem;
  problem.keys = keys;
  problem.gap_m = gap.gap_m;
  problem.no_surface = gap.no_surface;
  problem.normal_force_N = step.normal_force_N;
  problem.initial_pressure_Pa.resize(fine.cells_x, fine.cells_y);
  for (int j = 0; j < fine.cells_y; ++j) {
    for (int i = 0; i < fine.cells_x; ++i) problem.initial_pressure_Pa(i, j) = crossing.peak_pressure_Pa(i / 2, j / 2);
  }
  EdgePressureGridCheck check;
  NormalContactSolution s;
  try {
    s = solve_normal_contact(problem, HalfSpaceConvolution(fine.cells_x, fine.cells_y, dx, dy, E_star));
  } catch (const InputError&) {
    return check;  // the finer grid refused the step: no check
  }
  check.fine_iterations = s.iterations;
  check.fine_Pa = rail_end_edge_load(joint, gap, s.pressure_Pa, settings.edge_average_length_m).mean_pressure_Pa;
  // No contact at a cut on the fine cells: nothing to compare.
  check.converged = s.converged && check.fine_Pa > 0.0;
  if (check.converged) check.change = step.edge_pressure_Pa / check.fine_Pa - 1.0;
  return check;
}

}  // namespace

RailEndGap rail_end_gap(const JointParams& joint, const WheelParams& wheel, const RailEndContactSettings& settings,
                        double x_wheel_m, double x_centre_m, double y_centre_m, double dx_m, double dy_m) {
  const int nx = settings.cells_x;
  const int ny = settings.cells_y;
  RailEndGap out;
  out.dx_m = dx_m;
  out.dy_m = dy_m;
  out.x0_m = x_centre_m - (nx / 2) * dx_m;
  out.y0_m = y_centre_m - (ny / 2) * dy_m;
  out.gap_m.resize(nx, ny);
  out.no_surface.resize(nx, ny);
  out.incoming.resize(nx, ny);
  for (int j = 0; j < ny; ++j) {
    const double y = out.y0_m + j * dy_m;
    for (int i = 0; i < nx; ++i) {
      const double x = out.x0_m + i * dx_m;
      const double gap = wheel_bottom_m(wheel, x - x_wheel_m, y) - rail_height_m(joint, settings, x, y);
      out.no_surface(i, j) = !std::isfinite(gap);
      out.incoming(i, j) = std::isfinite(gap) && x <= cut_x_m(joint, y, 0);
      out.gap_m(i, j) = gap;
    }
  }
  const double lowest = out.no_surface.select(std::numeric_limits<double>::infinity(), out.gap_m).minCoeff();
  out.gap_m = out.no_surface.select(0.0, out.gap_m - lowest);
  return out;
}

RailEndCrossing rail_end_crossing(const JointParams& joint, const WheelParams& wheel,
                                  const RailEndContactSettings& settings, double normal_force_N, int steps) {
  return rail_end_crossing(joint, wheel, settings, [normal_force_N](double) { return normal_force_N; }, normal_force_N,
                           steps);
}

RailEndCrossing rail_end_crossing(const JointParams& joint, const WheelParams& wheel,
                                  const RailEndContactSettings& settings, const NormalForceAt& normal_force_N,
                                  double sizing_force_N, int steps) {
  return rail_end_crossing_observed(joint, wheel, settings, normal_force_N, sizing_force_N, steps, {});
}

RailEndCrossing rail_end_crossing_observed(const JointParams& joint, const WheelParams& wheel,
                                           const RailEndContactSettings& settings, const NormalForceAt& normal_force_N,
                                           double sizing_force_N, int steps, const RailEndFieldObserver& observe) {
  RailEndCrossing crossing;
  const double y_c = contact_y_m(joint, wheel);
  crossing.contact_y_m = y_c;
  // Hertz's ellipse on the incoming rail sizes the grid, from the
  // curvatures every Hertz ellipse of the program takes (contact_curvatures.h)
  // where the wheel touches it 30 mm before the cut (some four patch
  // half-lengths: on the incoming rail alone).
  const double x_before_m = contact_x_m(joint, wheel, settings, cut_x_m(joint, y_c, 0) - 0.03, y_c);
  const RelativeCurvatures relative = relative_curvatures(contact_curvatures_at(joint, wheel, 0, x_before_m, y_c));
  const double A = relative.along_x_per_m;
  const double B = relative.across_y_per_m;
  if (!(B > 1e-6)) {
    throw InputError("joint.crown_radius",
                     "the solved contact needs a head curved across the track where the wheel touches it "
                     "(joint.crown_radius > 0 or joint.rail_profile = \"60E1\"): a straight tread on a flat head is "
                     "a line contact");
  }
  const double E_star = combined_modulus_Pa(settings.youngs_modulus_Pa, settings.poisson_ratio,
                                            settings.youngs_modulus_Pa, settings.poisson_ratio);
  const HertzEllipse hertz = hertz_ellipse(A, B, E_star, sizing_force_N);
  crossing.hertz_semi_axis_x_m = hertz.semi_axis_x_m;
  crossing.hertz_semi_axis_y_m = hertz.semi_axis_y_m;
  const double dx = settings.window_over_axes * 2.0 * hertz.semi_axis_x_m / settings.cells_x;
  const double dy = settings.window_over_axes * 2.0 * hertz.semi_axis_y_m / settings.cells_y;
  const HalfSpaceConvolution convolution(settings.cells_x, settings.cells_y, dx, dy, E_star);

  // From the patch wholly on the incoming rail to wholly on the outgoing
  // one: its half-length and the cut's skew across its half-width, plus half
  // a semi-axis for the patch's spreading.
  const double a = hertz.semi_axis_x_m;
  const double skew = std::abs(cut_x_m(joint, y_c + hertz.semi_axis_y_m, 0) - cut_x_m(joint, y_c, 0));
  const double x_from = cut_x_m(joint, y_c, 0) - skew - 1.5 * a;
  const double x_to = cut_x_m(joint, y_c, 1) + skew + 1.5 * a;

  NormalContactProblem problem;
  problem.yield_pressure_Pa = settings.yield_pressure_Pa;
  problem.keys = {"contact_patch.normal_force", "contact_patch.yield_pressure", "contact_patch.cells_x",
                  "contact_patch.shape"};
  std::ostringstream larger;
  larger << "contact_patch.window_over_axes, here " << settings.window_over_axes
         << " Hertz axes; cells_x and cells_y raised alike keep the cells' size";
  problem.keys.larger_grid = larger.str();
  double peak = -1.0;
  double peak_plastic_area = 0.0;
  // The highest edge pressure's step, with its fields: the peak where the
  // largest cell is singular.
  double edge_peak = -1.0;
  std::size_t edge_peak_step = 0;
  RailEndGap edge_peak_gap;
  Eigen::ArrayXXd edge_peak_pressure_Pa;
  for (int k = 0; k < steps; ++k) {
    const double x_wheel = x_from + (x_to - x_from) * k / (steps - 1);
    const double x_centre = contact_x_m(joint, wheel, settings, x_wheel, y_c);
    RailEndGap gap = rail_end_gap(joint, wheel, settings, x_wheel, x_centre, y_c, dx, dy);
    RailEndStep step;
    step.x_wheel_m = x_wheel;
    step.t_s = (x_wheel - x_from) / wheel.speed_m_per_s;
    step.normal_force_N = normal_force_N(x_wheel);
    if (!std::isfinite(step.normal_force_N) || step.normal_force_N < 0.0) {
      throw InputError(problem.keys.load, "the load at x = " + std::to_string(x_wheel) +
                                              " m must be a finite force >= 0 [N], got " +
                                              std::to_string(step.normal_force_N));
    }
    if (step.normal_force_N == 0.0) {
      // The wheel in flight: no contact, and the next contact starts cold.
      step.converged = true;
      problem.initial_pressure_Pa.resize(0, 0);
      if (k == 0) crossing.initial_area_m2 = 0.0;
      if (observe) observe({step, {}, {}});
      crossing.steps.push_back(step);
      continue;
    }
    problem.gap_m = gap.gap_m;
    problem.no_surface = gap.no_surface;
    problem.normal_force_N = step.normal_force_N;
    const NormalContactSolution s = solve_normal_contact(problem, convolution);
    problem.initial_pressure_Pa = s.pressure_Pa;  // the next step starts from this one
    step.max_pressure_Pa = s.max_pressure_Pa;
    step.x_at_max_m = gap.x0_m + s.max_pressure_i * dx;
    step.y_at_max_m = gap.y0_m + s.max_pressure_j * dy;
    step.contact_area_m2 = s.contact_area_m2;
    step.plastic_area_m2 = s.plastic_area_m2;
    step.force_incoming_N = dx * dy * gap.incoming.select(s.pressure_Pa, 0.0).sum();
    step.force_outgoing_N = dx * dy * gap.incoming.select(0.0, s.pressure_Pa).sum();
    step.approach_m = s.approach_m;
    step.iterations = s.iterations;
    step.converged = s.converged;
    step.contact_at_edge = contact_at_edge(gap, s.pressure_Pa, settings.height_mismatch_m != 0.0 || joint.beta_rad != 0.0);
    crossing.max_pressure_singular =
        crossing.max_pressure_singular || (!settings.yield_pressure_Pa && step.contact_at_edge);
    if (!settings.yield_pressure_Pa && step.contact_at_edge) {
      crossing.contact_at_side = crossing.contact_at_side || contact_at_side(joint, gap, s.pressure_Pa);
    }
    // The elastic edge's measure; under a cap the pressure is bounded and
    // nothing reads it.
    if (!settings.yield_pressure_Pa) {
      const RailEndEdgeLoad edge = rail_end_edge_load(joint, gap, s.pressure_Pa, settings.edge_average_length_m);
      step.edge_pressure_Pa = edge.mean_pressure_Pa;
      step.x_of_edge_pressure_m = edge.x_m;
      step.y_of_edge_pressure_m = edge.y_m;
      step.edge_rail = edge.rail;
    }
    crossing.all_converged = crossing.all_converged && s.converged;
    crossing.max_plastic_area_m2 = std::max(crossing.max_plastic_area_m2, s.plastic_area_m2);
    if (k == 0) {
      crossing.initial_max_pressure_Pa = s.max_pressure_Pa;
      crossing.initial_area_m2 = s.contact_area_m2;
    }
    // Under a cap many steps reach it: the one with the largest plastic
    // area is where the plastic zone is widest.
    if (observe) observe({step, gap, s.pressure_Pa});
    // Of steps that tie, the first: a later one must be higher beyond the
    // tie (round-off would otherwise pick between mirror steps).
    const bool higher = s.max_pressure_Pa > peak && !ties(s.max_pressure_Pa, peak);
    const bool wider = ties(s.max_pressure_Pa, peak) && s.plastic_area_m2 > peak_plastic_area &&
                       !ties(s.plastic_area_m2, peak_plastic_area);
    if (!settings.yield_pressure_Pa && step.edge_pressure_Pa > edge_peak && !ties(step.edge_pressure_Pa, edge_peak)) {
      edge_peak = step.edge_pressure_Pa;
      edge_peak_step = crossing.steps.size();
      edge_peak_gap = gap;
      edge_peak_pressure_Pa = s.pressure_Pa;
    }
    if (peak < 0.0 || higher || wider) {
      peak = s.max_pressure_Pa;
      peak_plastic_area = s.plastic_area_m2;
      crossing.peak_step = crossing.steps.size();
      crossing.peak_gap = std::move(gap);
      crossing.peak_pressure_Pa = s.pressure_Pa;
    }
    crossing.steps.push_back(step);
  }
  if (crossing.max_pressure_singular) {
    crossing.peak_step = edge_peak_step;
    crossing.peak_gap = std::move(edge_peak_gap);
    crossing.peak_pressure_Pa = std::move(edge_peak_pressure_Pa);
    if (!crossing.contact_at_side) {
      crossing.edge_grid_check =
          check_edge_grid(joint, wheel, settings, crossing, E_star, problem.keys);
    }
  }
  if (peak >= 0.0) {
    const RailEndStep& top = crossing.steps[crossing.peak_step];
    for (std::size_t k = 0; k < crossing.steps.size(); ++k) {
      const RailEndStep& s = crossing.steps[k];
      if (k == crossing.peak_step || !(s.normal_force_N > 0.0)) continue;
      const bool tie =
          crossing.max_pressure_singular
              ? ties(s.edge_pressure_Pa, top.edge_pressure_Pa)
              : ties(s.max_pressure_Pa, top.max_pressure_Pa) && ties(s.plastic_area_m2, top.plastic_area_m2);
      if (tie) crossing.tied_peak_steps.push_back(k);
    }
  }
  return crossing;
}

}  // namespace railjoint
