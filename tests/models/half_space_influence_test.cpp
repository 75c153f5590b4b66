// Love's rectangle (models/half_space_influence.h) against two references
// computed here without its closed form: the polar integral of 1/r over the
// rectangle, and Boussinesq's point load far away.

#include <cmath>
#include <cstdio>
#include <numbers>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>

#include "models/half_space_influence.h"

namespace railjoint {
namespace {

constexpr double kPi = std::numbers::pi;

// For a point inside (or on the edge of) the rectangle |x'| <= a, |y'| <= b,
// the integral of dA / r over it is, in polar coordinates about the point,
// the integral over the direction phi of the distance rho(phi) to the
// rectangle's boundary (r dr dphi / r = dr dphi). rho has kinks at the four
// corners' directions: integrate between them.
double polar_integral_of_inverse_distance(double x, double y, double a, double b) {
  auto rho = [&](double phi) {
    const double c = std::cos(phi);
    const double s = std::sin(phi);
    double distance = std::numeric_limits<double>::infinity();
    if (c > 0) distance = std::min(distance, (a - x) / c);
    if (c < 0) distance = std::min(distance, (-a - x) / c);
    if (s > 0) distance = std::min(distance, (b - y) / s);
    if (s < 0) distance = std::min(distance, (-b - y) / s);
    return distance;
  };
  double corners[4] = {std::atan2(b - y, a - x), std::atan2(b - y, -a - x), std::atan2(-b - y, -a - x) + 2 * kPi,
                       std::atan2(-b - y, a - x) + 2 * kPi};
  double total = 0.0;
  double from = corners[3] - 2 * kPi;
  for (double to : corners) {
    total += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(rho, from, to, 10, 1e-13);
    from = to;
  }
  return total;
}

TEST(HalfSpaceInfluence, MatchesThePolarIntegralInsideAndOnTheEdge) {
  const double a = 0.5e-3;
  const double b = 0.3e-3;
  const double points[][2] = {{0, 0}, {0.2e-3, 0.1e-3}, {-0.45e-3, 0.25e-3}, {0.5e-3, 0.0}, {0.1e-3, -0.28e-3}};
  for (const auto& point : points) {
    const double closed = rectangle_deflection_factor_m(point[0], point[1], a, b);
    const double polar = polar_integral_of_inverse_distance(point[0], point[1], a, b);
    std::printf("(%g, %g) mm: closed %.15g, polar %.15g\n", 1e3 * point[0], 1e3 * point[1], closed, polar);
    // Quadrature of a piecewise-smooth integrand to 1e-13: agreement to 1e-11.
    EXPECT_NEAR(closed, polar, 1e-11 * polar);
  }
  // The centre of a square of side 2a: Johnson (1985) section 3.9 quotes
  // u = 2.24 p a (1 - nu^2) / E for one body, and one body's u is
  // p K (1 - nu^2) / (pi E): K / (pi a) = 2.24 (printed to 3 figures).
  EXPECT_NEAR(rectangle_deflection_factor_m(0, 0, a, a) / (kPi * a), 2.24, 0.005);
}

TEST(HalfSpaceInfluence, FarAwayIsBoussinesqsPointLoad) {
  // A load P = 4 a b p at distance r deflects by P / (pi E* r) (Johnson 3.21
  // for the pair), corrected by O((a/r)^2).
  const double a = 1e-3;
  const double b = 0.5e-3;
  const double E_star = combined_modulus_Pa(210e9, 0.3, 210e9, 0.3);
  const Eigen::ArrayXXd k = influence_coefficients_m_per_Pa(101, 101, 2 * a, 2 * b, E_star);
  for (int offset : {20, 50}) {
    const double r = offset * 2 * a;
    const double point_load = 4 * a * b / (kPi * E_star * r);
    const double coefficient = k(100 + offset, 100);
    std::printf("r = %g m: %.6e against %.6e\n", r, coefficient, point_load);
    EXPECT_NEAR(coefficient, point_load, 1.0 / (offset * offset) * point_load);
    EXPECT_EQ(k(100 - offset, 100), coefficient);  // even in x
  }
  // Steel on steel: E* = E / (2 (1 - nu^2)) = 115.38 GPa.
  EXPECT_NEAR(E_star, 210e9 / (2 * 0.91), 1.0);
}

}  // namespace
}  // namespace railjoint
