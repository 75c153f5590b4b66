// The FFT product (models/half_space_convolution.h) against the direct sum
// u(i, j) = sum over (k, l) of K(i - k, j - l) p(k, l), written here in
// O(N^2) from the influence matrix: the padding, the direction-by-direction
// transforms that skip the padding's zeros, the half-spectrum's layout and
// the kernel's real transform must all reproduce the linear (not circular)
// convolution. Grids odd and even, nx != ny and cells dx != dy, so that a
// swapped axis or an off-by-one in the wrap shows.

#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "models/half_space_convolution.h"
#include "models/half_space_influence.h"

namespace railjoint {
namespace {

Eigen::ArrayXXd direct_sum_m(const Eigen::ArrayXXd& p, const Eigen::ArrayXXd& k) {
  const Eigen::Index nx = p.rows();
  const Eigen::Index ny = p.cols();
  Eigen::ArrayXXd u = Eigen::ArrayXXd::Zero(nx, ny);
  for (Eigen::Index j = 0; j < ny; ++j) {
    for (Eigen::Index i = 0; i < nx; ++i) {
      for (Eigen::Index l = 0; l < ny; ++l) {
        for (Eigen::Index m = 0; m < nx; ++m) u(i, j) += k(nx - 1 + i - m, ny - 1 + j - l) * p(m, l);
      }
    }
  }
  return u;
}

TEST(HalfSpaceConvolution, EqualsTheDirectSum) {
  const double E_star = combined_modulus_Pa(210e9, 0.3, 210e9, 0.3);
  std::mt19937 random(38);
  std::uniform_real_distribution<double> pressure_Pa(0.0, 2e9);
  for (const auto& [nx, ny] : {std::pair{7, 5}, std::pair{6, 9}, std::pair{16, 16}, std::pair{1, 4}}) {
    const double dx = 0.3e-3;
    const double dy = 0.17e-3;
    const HalfSpaceConvolution convolution(nx, ny, dx, dy, E_star);
    const Eigen::ArrayXXd k = influence_coefficients_m_per_Pa(nx, ny, dx, dy, E_star);
    // Twice with different fields: the buffers' zeros must survive a product.
    for (int trial = 0; trial < 2; ++trial) {
      Eigen::ArrayXXd p(nx, ny);
      for (Eigen::Index n = 0; n < p.size(); ++n) p(n) = pressure_Pa(random);
      const Eigen::ArrayXXd expected = direct_sum_m(p, k);
      Eigen::ArrayXXd into;  // the allocation-free overload, from an empty array
      convolution.deflection_m(p, into);
      const double error = (convolution.deflection_m(p) - expected).abs().maxCoeff() / expected.abs().maxCoeff();
      const double error_into = (into - expected).abs().maxCoeff() / expected.abs().maxCoeff();
      std::printf("%d x %d, trial %d: max |FFT - direct| / max |u| = %.2e\n", nx, ny, trial, error);
      // Double-precision FFTs of a few hundred points round at some 1e-15.
      EXPECT_LT(error, 1e-12);
      EXPECT_LT(error_into, 1e-12);
    }
  }
}

}  // namespace
}  // namespace railjoint
