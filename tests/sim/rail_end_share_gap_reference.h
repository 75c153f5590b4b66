#pragma once
// The wheel pressed on two rail ends across an end-post gap, solved by the
// boundary-element method, as the reference for the force run's coupled
// spanning contact (sim/rail_end_patch_share.h) where the rail ends do not
// abut (tests/sim/rail_end_share_gap_test.cpp).
//
// Geometry (flat-topped rail ends on a crowned head, seen from above): the
// cut's centre line passes through the origin at the angle theta to the
// track (90 deg: square); s = x sin(theta) - y cos(theta) is the distance
// normal to it, the gap g (normal to the cut, as `joint.gap`) the band
// |s| < g / 2 that carries nothing (the end post), rail end 0 s < -g / 2,
// rail end 1 s > g / 2. Each rail end is bent along the track, falling at
// beta towards the joint (a dipped joint; beta 0: flat): its height is
// -beta x on rail end 0, +beta x on rail end 1 over all of its surface, its
// inclined end included. The undeformed gap under a cylindrical wheel (R_x
// 0.475 m) on the crown (R_y 0.3 m):
//   h(x, y) = (x - x_w)^2 / (2 R_x) + y^2 / (2 R_y) + beta x (rail end 0), - beta x (rail end 1).
//
// Two ways to take the bodies, both half-spaces (the rail ends are really
// quarter-spaces with a free end face; neither takes that):
//  - kOneHalfSpace: one half-space under both rail ends, continuous across
//    the gap, whose gap cells carry nothing (models/normal_contact_solver.h's
//    no_surface): the load on one rail end presses the other's surface
//    down as well as the wheel's (E* coupling);
//  - kRailEndsApart: each rail end its own half-space, the wheel one
//    half-space over both: the load on one rail end presses only the
//    wheel's surface down at the other, with the wheel's own compliance,
//    half the pair's for one steel (2 E* coupling). This is what the force
//    run assumes across a gap (force_contact_geometry.h,
//    spanning_coupling_modulus_Pa).
// The approach is u = K_w p + sum_i m_i K_r (m_i p), K_w = K_r = K / 2 (K
// the pair's half-space influence at E*, m_i rail end i's cells), solved by
// Polonsky and Keer's conjugate gradient (Wear 231, 1999, 206-219) written
// out here, apart from the models/ solver, which takes one operator only.

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>

#include "models/half_space_convolution.h"
#include "models/half_space_influence.h"
#include "models/hertz_contact.h"
#include "models/hertz_ellipse.h"

namespace railjoint::gap_reference {

constexpr double kRx = 0.475, kRy = 0.3;  // the wheel's rolling radius, the crown's radius [m]

struct GapJoint {
  double gap_m = 0.006;          ///< g, normal to the cut
  double cut_angle_rad = 1.5707963267948966;  ///< theta, the cut against the track
  double dip_rad = 0.0;          ///< beta: each rail end's fall towards the joint along the track
  double wheel_x_m = 0.0;        ///< x_w: the wheel's lowest point along the track
};

inline double cut_distance_m(const GapJoint& j, double x_m, double y_m) {
  return x_m * std::sin(j.cut_angle_rad) - y_m * std::cos(j.cut_angle_rad);
}

/// 0 or 1: the rail end at (x, y); -1 in the gap.
inline int rail_at(const GapJoint& j, double x_m, double y_m) {
  const double s = cut_distance_m(j, x_m, y_m);
  if (s < -0.5 * j.gap_m) return 0;
  if (s > 0.5 * j.gap_m) return 1;
  return -1;
}

/// h(x, y) above on rail end `rail`, not shifted [m].
inline double undeformed_gap_m(const GapJoint& j, int rail, double x_m, double y_m) {
  const double sign = rail == 1 ? -1.0 : 1.0;
  return (x_m - j.wheel_x_m) * (x_m - j.wheel_x_m) / (2 * kRx) + y_m * y_m / (2 * kRy) + sign * j.dip_rad * x_m;
}

struct TouchingPoint {
  double x_m = 0.0, y_m = 0.0;
  double gap_m = 0.0;        ///< h there
  bool on_cut_edge = false;  ///< at the rail end's edge (its patch cut off there)
};

/// Rail end i's lowest h: the quadratic's vertex where it lies on the rail
/// end, else the minimum along the cut's edge (h is a quadratic along it).
inline TouchingPoint touching_point(const GapJoint& j, int rail) {
  const double c = std::cos(j.cut_angle_rad), s = std::sin(j.cut_angle_rad);
  const double sign = rail == 0 ? 1.0 : -1.0;  // rail 0: h += beta x, rail 1: -= it
  TouchingPoint p;
  p.x_m = j.wheel_x_m - sign * j.dip_rad * kRx;
  p.y_m = 0.0;
  if (rail_at(j, p.x_m, p.y_m) != rail) {
    // The edge: s = -+ g / 2, points e + t (c, s) with e = -+ (g / 2) n.
    const double ex = -sign * 0.5 * j.gap_m * s, ey = sign * 0.5 * j.gap_m * c;
    const double t = -((ex - j.wheel_x_m) * c / kRx + ey * s / kRy + sign * j.dip_rad * c) / (c * c / kRx + s * s / kRy);
    p.x_m = ex + t * c;
    p.y_m = ey + t * s;
    p.on_cut_edge = true;
  }
  p.gap_m = undeformed_gap_m(j, rail, p.x_m, p.y_m);
  return p;
}

enum class Bodies { kOneHalfSpace, kRailEndsApart };

struct GapSolution {
  double approach_m = 0.0;             ///< delta, from the lowest h of the two rail ends
  std::array<double, 2> force_N{};     ///< each rail end's carried load
  std::array<double, 2> centroid_x_m{};  ///< where along x each rail end's load acts (0 where none)
  int iterations = 0;
  bool converged = false;
  int cells_x = 0, cells_y = 0;
};

/// The grid's box: the cells where h - h_min < reach_m (the contact lies
/// where h - h_min <= delta, u >= 0), plus two cells, from a scan of +-60 mm.
struct GridBox {
  double x0_m, y0_m;  ///< the first cell's corner
  int nx, ny;
};
inline GridBox grid_box(const GapJoint& j, double h_min_m, double reach_m, double cell_m) {
  double lo_x = 1e9, hi_x = -1e9, lo_y = 1e9, hi_y = -1e9;
  const double scan_m = 0.25e-3;
  for (double x = -0.06 + j.wheel_x_m; x <= 0.06 + j.wheel_x_m; x += scan_m) {
    for (double y = -0.06; y <= 0.06; y += scan_m) {
      const int rail = rail_at(j, x, y);
      if (rail < 0 || undeformed_gap_m(j, rail, x, y) - h_min_m >= reach_m) continue;
      lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x), lo_y = std::min(lo_y, y), hi_y = std::max(hi_y, y);
    }
  }
  const double margin_m = 2 * cell_m + scan_m;
  GridBox b;
  b.nx = static_cast<int>(std::ceil((hi_x - lo_x + 2 * margin_m) / cell_m));
  b.ny = static_cast<int>(std::ceil((hi_y - lo_y + 2 * margin_m) / cell_m));
  // Cell edges on multiples of cell_m: on the square cut's centre line and
  // the crown's top, so that a symmetric case is symmetric on the grid.
  b.x0_m = std::floor((0.5 * (lo_x + hi_x) - 0.5 * b.nx * cell_m) / cell_m) * cell_m;
  b.y0_m = std::floor((0.5 * (lo_y + hi_y) - 0.5 * b.ny * cell_m) / cell_m) * cell_m;
  b.nx += 1, b.ny += 1;  // the floor's shift
  return b;
}

/// Polonsky and Keer's conjugate gradient for g = h + u(p) - delta >= 0,
/// p >= 0, p g = 0, sum p A = W on the cells where `bears`, u = apply(p).
/// Writes the pressure [Pa] into p.
template <class Apply>
GapSolution polonsky_keer(const Eigen::ArrayXXd& h_m, const Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>& bears,
                          double load_N, double cell_area_m2, double tolerance, Apply apply, Eigen::ArrayXXd& p) {
  const Eigen::Index n = h_m.size();
  p = Eigen::ArrayXXd::Zero(h_m.rows(), h_m.cols());
  const double bearing_cells = static_cast<double>(bears.count());
  for (Eigen::Index k = 0; k < n; ++k) p(k) = bears(k) ? load_N / (bearing_cells * cell_area_m2) : 0.0;
  Eigen::ArrayXXd u(h_m.rows(), h_m.cols()), g(h_m.rows(), h_m.cols()), t = Eigen::ArrayXXd::Zero(h_m.rows(), h_m.cols());
  Eigen::ArrayXXd r(h_m.rows(), h_m.cols());
  double g_old = 1.0, mean_gap = 0.0;
  bool conjugate = false;
  GapSolution out;
  for (int it = 1; it <= 20000; ++it) {
    apply(p, u);
    g = h_m + u;
    double sum_g = 0.0;
    int contact = 0;
    for (Eigen::Index k = 0; k < n; ++k) {
      if (p(k) > 0.0) sum_g += g(k), ++contact;
    }
    mean_gap = sum_g / contact;
    g -= mean_gap;
    double G = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      if (p(k) > 0.0) G += g(k) * g(k);
    }
    for (Eigen::Index k = 0; k < n; ++k) t(k) = p(k) > 0.0 ? g(k) + (conjugate ? G / g_old : 0.0) * t(k) : 0.0;
    g_old = G;
    apply(t, r);
    double mean_r = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      if (p(k) > 0.0) mean_r += r(k);
    }
    mean_r /= contact;
    double gt = 0.0, rt = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      if (p(k) > 0.0) gt += g(k) * t(k), rt += (r(k) - mean_r) * t(k);
    }
    const double tau = gt / rt;
    const Eigen::ArrayXXd previous = p;
    bool overlap = false;
    for (Eigen::Index k = 0; k < n; ++k) {
      if (!bears(k)) continue;
      if (p(k) > 0.0) p(k) = std::max(0.0, p(k) - tau * t(k));
      if (p(k) == 0.0 && g(k) < 0.0) p(k) -= tau * g(k), overlap = true;  // tau g < 0: enters the contact
    }
    conjugate = !overlap;
    p *= load_N / (p.sum() * cell_area_m2);
    const double change = (p - previous).abs().sum() / p.sum();
    out.iterations = it;
    if (change < tolerance) {
      out.converged = true;
      break;
    }
  }
  out.approach_m = mean_gap;
  out.force_N = {0.0, 0.0};
  return out;
}

/// The problem on a box's cells: h - h_min, which cells bear, which are rail end 0's.
struct GapGrid {
  GridBox box;
  Eigen::ArrayXXd gap_m;
  Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic> bears, on_0;
};
/// The problem on a given box (kept from one wheel position to the next for
/// a warm start).
inline GapGrid gap_grid_on(const GapJoint& j, const GridBox& box, double h_min_m, double cell_m) {
  GapGrid g;
  g.box = box;
  const GridBox& b = g.box;
  g.gap_m.resize(b.nx, b.ny);
  g.bears.resize(b.nx, b.ny);
  g.on_0.resize(b.nx, b.ny);
  for (int i = 0; i < b.nx; ++i) {
    for (int k = 0; k < b.ny; ++k) {
      const double x = b.x0_m + (i + 0.5) * cell_m, y = b.y0_m + (k + 0.5) * cell_m;
      const int rail = rail_at(j, x, y);
      g.bears(i, k) = rail >= 0;
      g.on_0(i, k) = rail == 0;
      g.gap_m(i, k) = undeformed_gap_m(j, std::max(rail, 0), x, y) - h_min_m;
    }
  }
  return g;
}
inline GapGrid gap_grid(const GapJoint& j, double h_min_m, double reach_m, double cell_m) {
  return gap_grid_on(j, grid_box(j, h_min_m, reach_m, cell_m), h_min_m, cell_m);
}

/// Twice Hertz's approach under the whole load on one rail end [m].
inline double first_reach_m(double load_N) {
  const auto hertz = elliptical_hertz({0.5 / kRx, 0.5 / kRy}, HertzMaterial{});
  return 2.0 * hertz->hertz_constant_m_per_N2_3 * std::pow(load_N, 2.0 / 3.0);
}

inline double lowest_gap_m(const GapJoint& j) {
  return std::min(touching_point(j, 0).gap_m, touching_point(j, 1).gap_m);
}

/// The contact under the load W on the two rail ends on square cells of
/// cell_m, the bodies taken as `bodies` (E* the pair's); only_rail 0 or 1:
/// that rail end alone (the other's cells carry nothing), its approach
/// from its own lowest point. The box is grown while the pressure reaches
/// its border.
inline GapSolution solve_gap_contact(const GapJoint& j, double load_N, double cell_m, Bodies bodies,
                                     double combined_modulus_Pa, double tolerance = 1e-9, int only_rail = -1) {
  const double h_min_m = only_rail < 0 ? lowest_gap_m(j) : touching_point(j, only_rail).gap_m;
  double reach_m = first_reach_m(load_N);
  for (int attempt = 0; attempt < 4; ++attempt, reach_m *= 1.5) {
    GapGrid grid = gap_grid(j, h_min_m, reach_m, cell_m);
    if (only_rail >= 0) grid.bears = grid.bears && (grid.on_0 == (only_rail == 0));
    const int nx = grid.box.nx, ny = grid.box.ny;
    const HalfSpaceConvolution convolution(nx, ny, cell_m, cell_m, combined_modulus_Pa);
    Eigen::ArrayXXd part(nx, ny), part_u(nx, ny);
    const auto one_half_space = [&](const Eigen::ArrayXXd& p, Eigen::ArrayXXd& u) { convolution.deflection_m(p, u); };
    const auto rail_ends_apart = [&](const Eigen::ArrayXXd& p, Eigen::ArrayXXd& u) {
      // The wheel's half under all of p, each rail end's under its own.
      convolution.deflection_m(p, u);
      u *= 0.5;
      for (const bool rail_0 : {true, false}) {
        const auto mine = grid.bears && (grid.on_0 == rail_0);
        part = mine.select(p, 0.0);
        convolution.deflection_m(part, part_u);
        u += mine.select(0.5 * part_u, 0.0);
      }
    };
    const double area_m2 = cell_m * cell_m;
    Eigen::ArrayXXd p;
    GapSolution s = bodies == Bodies::kOneHalfSpace
                        ? polonsky_keer(grid.gap_m, grid.bears, load_N, area_m2, tolerance, one_half_space, p)
                        : polonsky_keer(grid.gap_m, grid.bears, load_N, area_m2, tolerance, rail_ends_apart, p);
    const double border_Pa = std::max({p.row(0).maxCoeff(), p.row(nx - 1).maxCoeff(), p.col(0).maxCoeff(),
                                       p.col(ny - 1).maxCoeff()});
    if (border_Pa > 0.0) continue;
    s.force_N[0] = grid.on_0.select(p, 0.0).sum() * area_m2;
    s.force_N[1] = (grid.bears && !grid.on_0).select(p, 0.0).sum() * area_m2;
    Eigen::ArrayXXd x_m(nx, ny);
    for (int i = 0; i < nx; ++i) x_m.row(i).setConstant(grid.box.x0_m + (i + 0.5) * cell_m);
    const Eigen::ArrayXXd px = p * x_m;
    if (s.force_N[0] > 0.0) s.centroid_x_m[0] = grid.on_0.select(px, 0.0).sum() * area_m2 / s.force_N[0];
    if (s.force_N[1] > 0.0) s.centroid_x_m[1] = (grid.bears && !grid.on_0).select(px, 0.0).sum() * area_m2 / s.force_N[1];
    s.cells_x = nx;
    s.cells_y = ny;
    return s;
  }
  throw std::runtime_error("gap contact: the patch reaches the grid's border");
}

}  // namespace railjoint::gap_reference
