// The FFT product (models/half_space_convolution.h) against the direct sum
// u(i, j) = sum over (k, l) of K(i - k, j - l) p(k, l), written here in
// O(N^2) from the influence matrix: the padding, the direction-by-direction
// transforms that skip the padding's zeros, the half-spectrum's layout and
// the kernel's real transform must all reproduce the linear (not circular)
// convolution. Grids odd and even, nx != ny and cells dx != dy, so that a
// swapped axis or an off-by-one in the wrap shows. And the solver's
// preconditioner against Johnson's sinusoidal loading.

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

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

// The solver's correction for the few cells a step moved: the direct sum of
// those cells alone, added to what is there, equals the product of a field
// holding only them (the FFT's rounding apart).
TEST(HalfSpaceConvolution, CellDeflectionsAddTheDirectSum) {
  const double E_star = combined_modulus_Pa(210e9, 0.3, 210e9, 0.3);
  const int nx = 9;
  const int ny = 6;
  const HalfSpaceConvolution convolution(nx, ny, 0.3e-3, 0.17e-3, E_star);
  // Corner and inner cells, so that an offset off by one row or column shows.
  const std::vector<Eigen::Index> cells = {0, nx - 1, 4 + 2 * nx, nx * ny - 1};
  const std::vector<double> pressures_Pa = {1.1e9, -0.4e9, 2.0e9, 0.7e9};
  Eigen::ArrayXXd field = Eigen::ArrayXXd::Zero(nx, ny);
  for (std::size_t c = 0; c < cells.size(); ++c) field(cells[c]) = pressures_Pa[c];
  const Eigen::ArrayXXd start = Eigen::ArrayXXd::Constant(nx, ny, 1e-5);
  Eigen::ArrayXXd added = start;
  convolution.add_cell_deflections_m(cells, pressures_Pa, added);
  const Eigen::ArrayXXd expected = start + convolution.deflection_m(field);
  const double error = (added - expected).abs().maxCoeff() / (expected - start).abs().maxCoeff();
  std::printf("cells added by direct sum against the FFT product: %.2e\n", error);
  EXPECT_LT(error, 1e-12);  // the FFT's rounding, some 1e-15
}

// The product on a box (the solver's K t on the contact's cells): for a
// field that vanishes off the box, the deflection on the box is the whole
// grid's product there; the cells off the box are left as they were.
TEST(HalfSpaceConvolution, ABoxProductIsTheWholeProductOnTheBox) {
  const double E_star = combined_modulus_Pa(210e9, 0.3, 210e9, 0.3);
  const int nx = 40;
  const int ny = 30;
  const HalfSpaceConvolution convolution(nx, ny, 0.3e-3, 0.17e-3, E_star);
  // Cells 9..21 x 5..16: sides 13 and 12 round up to the fast sizes 14 and 12.
  const auto box = convolution.product_box(9, 21, 5, 16);
  ASSERT_TRUE(box.has_value());
  EXPECT_EQ(box->cells_x, 14);
  EXPECT_EQ(box->cells_y, 12);
  EXPECT_EQ(box->first_i, 9);
  EXPECT_EQ(box->first_j, 5);
  // Near the far edges the box is shifted back inside the grid.
  const auto edge = convolution.product_box(30, 39, 25, 29);
  ASSERT_TRUE(edge.has_value());
  EXPECT_EQ(edge->first_i + edge->cells_x, nx);
  EXPECT_EQ(edge->first_j + edge->cells_y, ny);
  EXPECT_LE(edge->first_i, 30);
  EXPECT_LE(edge->first_j, 25);
  // A box nearly the grid's size gains nothing: none.
  EXPECT_FALSE(convolution.product_box(0, 38, 0, 28).has_value());

  std::mt19937 random(38);
  std::uniform_real_distribution<double> pressure_Pa(0.0, 2e9);
  Eigen::ArrayXXd field = Eigen::ArrayXXd::Zero(nx, ny);
  for (int j = 6; j < 15; ++j) {
    for (int i = 10; i < 21; ++i) field(i, j) = pressure_Pa(random);
  }
  const Eigen::ArrayXXd whole = convolution.deflection_m(field);
  Eigen::ArrayXXd on_box = Eigen::ArrayXXd::Constant(nx, ny, -1.0);
  for (int trial = 0; trial < 2; ++trial) convolution.box_deflection_m(field, *box, on_box);  // the kept plan too
  const auto inside = on_box.block(box->first_i, box->first_j, box->cells_x, box->cells_y);
  const double error = (inside - whole.block(box->first_i, box->first_j, box->cells_x, box->cells_y)).abs().maxCoeff() /
                       whole.abs().maxCoeff();
  std::printf("box product against the whole product on the box: %.2e\n", error);
  EXPECT_LT(error, 1e-12);  // two FFT sizes' rounding, some 1e-15
  EXPECT_EQ(on_box.topRows(box->first_i).maxCoeff(), -1.0);
  EXPECT_EQ(on_box.bottomRows(nx - box->first_i - box->cells_x).maxCoeff(), -1.0);
  EXPECT_EQ(on_box.leftCols(box->first_j).maxCoeff(), -1.0);
  EXPECT_EQ(on_box.rightCols(ny - box->first_j - box->cells_y).maxCoeff(), -1.0);
}

// The solver's preconditioner (approximate_pressure_Pa), against what a
// preconditioner must be and what it stands for. A pressure p cos(k x) on
// a half-space deflects the surface by 2 p / (E* k) cos(k x) (Johnson 1985,
// the Boussinesq kernel transformed: its symbol is 2 / (E* |k|)), so the
// approximate inverse must give the pressure back from that deflection at
// wavelengths long against the cells: within (k h)^2 / 24 (the 5-point
// Laplacian's symbol against k^2; 0.16 % at 32 cells a wavelength, for
// which 0.2 % is allowed), along x, along y and obliquely, with cells
// dx != dy. It must be symmetric (x . M y = y . M x) and positive on
// fields of zero mean: random fields, to rounding.
TEST(HalfSpaceConvolution, ApproximatePressureInvertsLongWavesSymmetricPositive) {
  const double E_star = combined_modulus_Pa(210e9, 0.3, 210e9, 0.3);
  const int nx = 64;
  const int ny = 96;
  const double dx = 0.3e-3;
  const double dy = 0.2e-3;
  const HalfSpaceConvolution convolution(nx, ny, dx, dy, E_star);
  const double pi = 3.14159265358979323846;
  // Whole waves on the periodic grid: (waves along x, waves along y).
  for (const auto& [wx, wy] : {std::pair{2, 0}, std::pair{0, 3}, std::pair{2, 3}}) {
    const double kx = 2 * pi * wx / (nx * dx);
    const double ky = 2 * pi * wy / (ny * dy);
    const double k = std::hypot(kx, ky);
    Eigen::ArrayXXd deflection(nx, ny);
    Eigen::ArrayXXd pressure_expected(nx, ny);
    const double amplitude_Pa = 1e9;
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const double c = std::cos(kx * i * dx + ky * j * dy);
        pressure_expected(i, j) = amplitude_Pa * c;
        deflection(i, j) = 2 * amplitude_Pa / (E_star * k) * c;
      }
    }
    Eigen::ArrayXXd pressure;
    convolution.approximate_pressure_Pa(deflection, pressure);
    const double error = (pressure - pressure_expected).abs().maxCoeff() / amplitude_Pa;
    std::printf("waves %d x %d (32 cells a wavelength along each axis with waves): max |M u - p| / p = %.2e\n",
                wx, wy, error);
    EXPECT_LT(error, 2e-3);
  }
  std::mt19937 random(38);
  std::normal_distribution<double> gap_m(0.0, 1e-6);
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::ArrayXXd x(nx, ny), y(nx, ny);
    for (Eigen::Index n = 0; n < x.size(); ++n) {
      x(n) = gap_m(random);
      y(n) = gap_m(random);
    }
    x -= x.mean();
    Eigen::ArrayXXd mx, my;
    convolution.approximate_pressure_Pa(x, mx);
    convolution.approximate_pressure_Pa(y, my);
    const double xmy = (x * my).sum();
    const double ymx = (y * mx).sum();
    const double xmx = (x * mx).sum();
    std::printf("random %d: x.My %.6e, y.Mx %.6e, x.Mx %.6e\n", trial, xmy, ymx, xmx);
    EXPECT_NEAR(xmy, ymx, 1e-12 * (x * mx).abs().sum());
    EXPECT_GT(xmx, 0.0);
  }
}

}  // namespace
}  // namespace railjoint
