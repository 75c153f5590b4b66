#include "models/smoothing_spline.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>
#include <utility>

#include <Eigen/Dense>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace railjoint {

namespace {

struct Fit {
  std::vector<double> g, gamma;
  double rms = 0.0;
};

void measure(Fit& fit, const std::vector<double>& v) {
  double sum = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) sum += (v[i] - fit.g[i]) * (v[i] - fit.g[i]);
  fit.rms = std::sqrt(sum / static_cast<double>(v.size()));
}

// Green and Silverman's Reinsch algorithm (sec. 2.3.3): with h_i the knot
// spacings, Q the n x (n-2) second-difference matrix (column j: 1/h_j,
// -1/h_j - 1/h_{j+1}, 1/h_{j+1} at rows j, j+1, j+2) and R the (n-2) x (n-2)
// tridiagonal (h_j + h_{j+1})/3, h_{j+1}/6, the interior second derivatives
// solve (R + alpha Q^T Q) gamma = Q^T v and the residuals are alpha Q gamma.
// The matrix is pentadiagonal and positive definite: a sparse LDL^T in the
// natural order is O(n).
Fit fit_with(const std::vector<double>& x, const std::vector<double>& v, double alpha) {
  const int n = static_cast<int>(x.size());
  const int m = n - 2;
  std::vector<double> a(m), b(m), c(m);
  for (int j = 0; j < m; ++j) {
    const double h0 = x[j + 1] - x[j];
    const double h1 = x[j + 2] - x[j + 1];
    a[j] = 1.0 / h0;
    b[j] = -1.0 / h0 - 1.0 / h1;
    c[j] = 1.0 / h1;
  }
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(5 * static_cast<std::size_t>(m));
  Eigen::VectorXd rhs(m);
  for (int j = 0; j < m; ++j) {
    const double h0 = x[j + 1] - x[j];
    const double h1 = x[j + 2] - x[j + 1];
    entries.emplace_back(j, j, (h0 + h1) / 3.0 + alpha * (a[j] * a[j] + b[j] * b[j] + c[j] * c[j]));
    if (j + 1 < m) {
      const double off = h1 / 6.0 + alpha * (b[j] * a[j + 1] + c[j] * b[j + 1]);
      entries.emplace_back(j, j + 1, off);
      entries.emplace_back(j + 1, j, off);
    }
    if (j + 2 < m) {
      entries.emplace_back(j, j + 2, alpha * c[j] * a[j + 2]);
      entries.emplace_back(j + 2, j, alpha * c[j] * a[j + 2]);
    }
    rhs[j] = a[j] * v[j] + b[j] * v[j + 1] + c[j] * v[j + 2];
  }
  Eigen::SparseMatrix<double> matrix(m, m);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> solver(matrix);
  const Eigen::VectorXd gamma = solver.solve(rhs);
  Fit fit;
  fit.gamma.assign(n, 0.0);
  for (int j = 0; j < m; ++j) fit.gamma[j + 1] = gamma[j];
  fit.g = v;
  for (int j = 0; j < m; ++j) {
    fit.g[j] -= alpha * a[j] * gamma[j];
    fit.g[j + 1] -= alpha * b[j] * gamma[j];
    fit.g[j + 2] -= alpha * c[j] * gamma[j];
  }
  measure(fit, v);
  return fit;
}

// The limit alpha -> infinity: the least-squares straight line (of points
// less their parabola: 0, so the spline's limit is the parabola).
Fit straight_line(const std::vector<double>& x, const std::vector<double>& v) {
  const double n = static_cast<double>(x.size());
  const double x_mean = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double v_mean = std::accumulate(v.begin(), v.end(), 0.0) / n;
  double sxx = 0.0, sxv = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - x_mean) * (x[i] - x_mean);
    sxv += (x[i] - x_mean) * (v[i] - v_mean);
  }
  const double slope = sxv / sxx;
  Fit fit;
  fit.gamma.assign(x.size(), 0.0);
  for (const double xi : x) fit.g.push_back(v_mean + slope * (xi - x_mean));
  measure(fit, v);
  return fit;
}

}  // namespace

SmoothingSpline::SmoothingSpline(std::vector<double> x, const std::vector<double>& points, double rms_residual)
    : x_(std::move(x)) {
  assert(x_.size() >= 4 && x_.size() == points.size() && rms_residual >= 0.0);
  // The least-squares parabola, in x about the middle (well conditioned).
  x_mid_ = 0.5 * (x_.front() + x_.back());
  Eigen::MatrixXd basis(x_.size(), 3);
  Eigen::VectorXd rhs(x_.size());
  for (std::size_t i = 0; i < x_.size(); ++i) {
    const double u = x_[i] - x_mid_;
    basis.row(static_cast<Eigen::Index>(i)) << 1.0, u, u * u;
    rhs[static_cast<Eigen::Index>(i)] = points[i];
  }
  const Eigen::Vector3d c = basis.colPivHouseholderQr().solve(rhs);
  for (int k = 0; k < 3; ++k) c_[k] = c[k];
  std::vector<double> v(points.size());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = points[i] - trend(x_[i]);
  Fit best = rms_residual == 0.0 ? fit_with(x_, v, 0.0) : straight_line(x_, v);
  if (rms_residual > 0.0 && best.rms > rms_residual) {
    // The residual grows with alpha from 0 (interpolation) to the parabola's:
    // bracket the target on a log scale from the spacing's natural unit
    // h^3 (where R and alpha Q^T Q are of one size), then bisect.
    const double h = (x_.back() - x_.front()) / static_cast<double>(x_.size() - 1);
    double lo = 0.0, hi = h * h * h;
    Fit at_hi = fit_with(x_, v, hi);
    for (int i = 0; i < 200 && at_hi.rms <= rms_residual; ++i) {
      lo = hi;
      hi *= 10.0;
      at_hi = fit_with(x_, v, hi);
    }
    if (lo == 0.0) {
      lo = hi;
      for (int i = 0; i < 200 && fit_with(x_, v, lo).rms > rms_residual; ++i) lo /= 10.0;
    }
    best = fit_with(x_, v, lo);
    // On log alpha to a part in 1e6 of alpha; the residual moves less.
    while (hi / lo > 1.0 + 1e-6) {
      const double mid = std::sqrt(lo * hi);
      Fit at_mid = fit_with(x_, v, mid);
      if (at_mid.rms <= rms_residual) {
        lo = mid;
        best = std::move(at_mid);
      } else {
        hi = mid;
      }
    }
  }
  g_ = std::move(best.g);
  for (std::size_t i = 0; i < g_.size(); ++i) g_[i] += trend(x_[i]);
  if (rms_residual == 0.0) g_ = points;  // through the points themselves, not their round trip through the trend
  gamma_ = std::move(best.gamma);
}

double SmoothingSpline::operator()(double x) const {
  if (x <= x_.front()) return g_.front() + prime(x_.front()) * (x - x_.front());
  if (x >= x_.back()) return g_.back() + prime(x_.back()) * (x - x_.back());
  return trend(x) + about_trend(x);
}

double SmoothingSpline::about_trend(double x) const {
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin()) - 1;
  const double h = x_[i + 1] - x_[i];
  const double A = (x_[i + 1] - x) / h;
  const double B = 1.0 - A;
  const double gi = g_[i] - trend(x_[i]), gj = g_[i + 1] - trend(x_[i + 1]);
  return A * gi + B * gj + ((A * A * A - A) * gamma_[i] + (B * B * B - B) * gamma_[i + 1]) * h * h / 6.0;
}

double SmoothingSpline::prime(double x) const {
  x = std::clamp(x, x_.front(), x_.back());
  std::size_t i = static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin());
  i = std::clamp<std::size_t>(i, 1, x_.size() - 1) - 1;
  const double h = x_[i + 1] - x_[i];
  const double A = (x_[i + 1] - x) / h;
  const double B = 1.0 - A;
  return trend_prime(x) + (g_[i + 1] - trend(x_[i + 1]) - g_[i] + trend(x_[i])) / h + (-(3.0 * A * A - 1.0) * gamma_[i] + (3.0 * B * B - 1.0) * gamma_[i + 1]) * h / 6.0;
}

}  // namespace railjoint
