#include "models/point_scatter.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <Eigen/Dense>

namespace railjoint {

std::optional<double> point_scatter_m(const std::vector<double>& y_m, const std::vector<double>& value_m) {
  const std::size_t n = y_m.size();
  if (n < 5 || value_m.size() != n) return std::nullopt;
  std::vector<double> scaled;  // |residual| / sqrt(1 - leverage): one point's scatter
  scaled.reserve(n - 4);
  for (std::size_t i = 2; i + 2 < n; ++i) {
    // The window's abscissae about the middle point, over its span: the
    // cubic's normal equations stay well conditioned at any spacing.
    const double span = y_m[i + 2] - y_m[i - 2];
    Eigen::Matrix<double, 5, 4> basis;
    Eigen::Matrix<double, 5, 1> values;
    for (int k = 0; k < 5; ++k) {
      const double t = (y_m[i - 2 + static_cast<std::size_t>(k)] - y_m[i]) / span;
      basis.row(k) << 1.0, t, t * t, t * t * t;
      values(k) = value_m[i - 2 + static_cast<std::size_t>(k)] - value_m[i];
    }
    const Eigen::Matrix4d normal = basis.transpose() * basis;
    const Eigen::LDLT<Eigen::Matrix4d> solve(normal);
    const Eigen::Vector4d coefficients = solve.solve(basis.transpose() * values);
    const double residual = values(2) - basis.row(2).dot(coefficients);
    const double leverage = basis.row(2).dot(solve.solve(basis.row(2).transpose()));
    if (!(leverage < 1.0)) continue;  // five points on a cubic's knots: no freedom left here
    scaled.push_back(std::abs(residual) / std::sqrt(1.0 - leverage));
  }
  if (scaled.empty()) return std::nullopt;
  const auto middle = scaled.begin() + static_cast<std::ptrdiff_t>(scaled.size() / 2);
  std::nth_element(scaled.begin(), middle, scaled.end());
  return *middle / 0.6744897501960817;  // the median of |N(0, 1)|
}

}  // namespace railjoint
