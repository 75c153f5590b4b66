#include "models/half_space_influence.h"

#include <cmath>
#include <numbers>

namespace railjoint {

double combined_modulus_Pa(double E1, double nu1, double E2, double nu2) {
  return 1.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2);
}

namespace {

// x ln(y + r) + y ln(x + r) less the x ln|x| and y ln|y| that cancel between
// corners sharing an x or a y: finite at x = 0 or y = 0 and free of cancellation.
double corner_term_m(double x, double y) {
  double value = 0.0;
  if (x != 0.0) value += x * std::asinh(y / std::abs(x));
  if (y != 0.0) value += y * std::asinh(x / std::abs(y));
  return value;
}

}  // namespace

double rectangle_deflection_factor_m(double x, double y, double a, double b) {
  return corner_term_m(x + a, y + b) - corner_term_m(x + a, y - b) - corner_term_m(x - a, y + b) +
         corner_term_m(x - a, y - b);
}

Eigen::ArrayXXd influence_coefficients_m_per_Pa(int nx, int ny, double cell_x_m, double cell_y_m,
                                                double combined_modulus) {
  Eigen::ArrayXXd coefficients(2 * nx - 1, 2 * ny - 1);
  const double scale = 1.0 / (std::numbers::pi * combined_modulus);
  // K is even in x and in y: compute one quadrant, mirror the rest.
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const double k = scale * rectangle_deflection_factor_m(i * cell_x_m, j * cell_y_m, cell_x_m / 2, cell_y_m / 2);
      coefficients(nx - 1 + i, ny - 1 + j) = k;
      coefficients(nx - 1 - i, ny - 1 + j) = k;
      coefficients(nx - 1 + i, ny - 1 - j) = k;
      coefficients(nx - 1 - i, ny - 1 - j) = k;
    }
  }
  return coefficients;
}

}  // namespace railjoint
