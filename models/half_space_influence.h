#pragma once
// The elastic half-space's surface deflection under a uniform pressure on a
// rectangle (Love, 1929; Johnson, Contact Mechanics, 1985, section 3.9): the
// influence coefficients of a boundary-element contact solver whose pressure
// is constant over each rectangular cell.
//
// A pressure p on |x'| <= a, |y'| <= b deflects the surface at (x, y) by
//   u_z = p / (pi E*) K(x, y),   K = F(x+a, y+b) - F(x+a, y-b) - F(x-a, y+b) + F(x-a, y-b),
//   F(x, y) = x asinh(y / |x|) + y asinh(x / |y|)   (each term 0 where its factor is 0),
// the integral of 1/r over the rectangle written with asinh so that no
// logarithm of a difference of nearly equal numbers appears. E* is the
// combined modulus of the two bodies, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,
// so u_z is the two surfaces' approach, not one body's.

#include <Eigen/Core>

namespace railjoint {

/// E* from the two bodies' Young's moduli [Pa] and Poisson's ratios [-]:
/// 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2. Steel on steel (210 GPa, 0.3): 115.4 GPa.
double combined_modulus_Pa(double youngs_modulus_1_Pa, double poisson_ratio_1, double youngs_modulus_2_Pa,
                            double poisson_ratio_2);

/// K(x, y) above [m]: the deflection at (x, y) [m] from the centre of a cell of
/// half-sizes half_x_m, half_y_m under unit pressure, times pi E*.
double rectangle_deflection_factor_m(double x_m, double y_m, double half_x_m, double half_y_m);

/// The influence matrix of a grid of nx x ny cells of size cell_x_m x cell_y_m
/// for offsets -(n-1)..(n-1) cells in each direction: entry (i + nx - 1,
/// j + ny - 1) is the deflection [m] at offset (i, j) cells per 1 Pa on a cell.
Eigen::ArrayXXd influence_coefficients_m_per_Pa(int nx, int ny, double cell_x_m, double cell_y_m,
                                                double combined_modulus_Pa);

}  // namespace railjoint
