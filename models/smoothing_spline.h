#pragma once
// A cubic smoothing spline through noisy points (Reinsch, "Smoothing by
// spline functions", Numer. Math. 10 (1967) 177-183; the penalised form of
// Green and Silverman, "Nonparametric Regression and Generalized Linear
// Models", 1994, ch. 2): of the natural cubic splines g with knots at the
// points x_i, the one that minimises
//   sum_i (v_i - g(x_i))^2 + alpha * integral g''(x)^2 dx,
// alpha chosen so that the residuals v_i - g(x_i) have the RMS asked for.
// Reinsch's criterion: with noise of standard deviation sigma the curve
// should leave residuals of about sigma, no more (it would flatten the
// shape) and no less (it would follow the noise). The spline smooths the
// points less their least-squares parabola, so its penalty pulls the
// curvature towards the profile's mean curvature, not towards a straight
// line: a natural spline's g'' = 0 at its ends cost an exactly sampled
// 300 mm crown 14 um there at a 2 um RMS (1e-2 um with the parabola).
// alpha -> infinity is the parabola, alpha = 0 the interpolating spline.

#include <vector>

namespace railjoint {

class SmoothingSpline {
 public:
  /// Needs >= 4 points, x increasing, rms_residual >= 0. Where even the
  /// least-squares parabola leaves no more than rms_residual, it is that
  /// parabola; rms_residual 0 interpolates (alpha = 0, g(x_i) the points).
  SmoothingSpline(std::vector<double> x, const std::vector<double>& v, double rms_residual);

  double operator()(double x) const;    ///< g(x); beyond the end knots, the end's straight line
  double prime(double x) const;         ///< g'(x)
  const std::vector<double>& knot_values() const { return g_; }  ///< g(x_i)

 private:
  double about_trend(double x) const;  // the spline part, inside the knots
  double trend(double x) const { return c_[0] + (x - x_mid_) * (c_[1] + (x - x_mid_) * c_[2]); }
  double trend_prime(double x) const { return c_[1] + 2.0 * (x - x_mid_) * c_[2]; }

  std::vector<double> x_, g_;  // knots, g(x_i)
  std::vector<double> gamma_;  // the spline about the parabola: its g''(x_i), 0 at both ends
  double x_mid_ = 0.0;         // the parabola c0 + c1 (x - x_mid) + c2 (x - x_mid)^2
  double c_[3] = {0.0, 0.0, 0.0};
};

}  // namespace railjoint
