#pragma once
// The half-space's deflection under a pressure field on a regular grid,
// u = K * p (models/half_space_influence.h), by FFT (FFTW3): the field is
// zero-padded to twice its size in each direction so that the circular
// convolution equals the linear one (Liu, Wang and Liu, Wear 243, 2000), and
// a product costs O(N log N) instead of O(N^2).
//
// The 2D transform is done one direction at a time so that the padding's
// zeros are not transformed and the unwanted half of the result is not
// computed: along x only the ny columns that hold pressure, along y all
// nx + 1 half-spectrum columns, and back along x only the ny columns that
// are returned. That is 3/4 of a full padded 2D r2c/c2r pair's work.
//
// It also gives an iterative solver's preconditioner, an approximate
// inverse of K (approximate_pressure_Pa): K's symbol is 2 / (E* |k|), so
// its inverse is the first-order operator E* |k| / 2, applied by one
// unpadded transform pair (the grid taken as periodic).

#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace railjoint {

class HalfSpaceConvolution {
 public:
  /// A grid of nx x ny cells (x along the rows of the fields) of size
  /// cell_x_m x cell_y_m, two bodies of combined modulus E* [Pa].
  HalfSpaceConvolution(int nx, int ny, double cell_x_m, double cell_y_m, double combined_modulus_Pa);
  ~HalfSpaceConvolution();
  HalfSpaceConvolution(const HalfSpaceConvolution&) = delete;
  HalfSpaceConvolution& operator=(const HalfSpaceConvolution&) = delete;

  /// The deflection [m] (nx x ny) under the pressure field [Pa] (nx x ny).
  /// Uses the object's own FFT buffers: one object per thread.
  Eigen::ArrayXXd deflection_m(const Eigen::ArrayXXd& pressure_Pa) const;

  /// The same into `deflection` (resized to nx x ny if it is not): no
  /// allocation once it has the grid's size, for an iterative solver.
  void deflection_m(const Eigen::ArrayXXd& pressure_Pa, Eigen::ArrayXXd& deflection) const;

  /// Adds the deflection [m] under pressures [Pa] on a few cells to
  /// `deflection` (nx x ny) by the direct sum over the influence matrix:
  /// O(cells x N) against the FFT's O(N log N), for an iterative solver's
  /// correction where a step changed a few cells only.
  void add_cell_deflections_m(const std::vector<Eigen::Index>& cells, const std::vector<double>& pressures_Pa,
                              Eigen::ArrayXXd& deflection) const;

  /// How many cells add_cell_deflections_m takes for about half the cost of
  /// one FFT product (N operations a cell against about 4N log2(4N) for the
  /// padded transforms; half: see the .cpp).
  int direct_cells_per_product() const { return direct_cells_per_product_; }

  /// A rectangle of cells [first_i, first_i + cells_x) x [first_j, first_j + cells_y).
  struct CellBox {
    int first_i = 0, first_j = 0, cells_x = 0, cells_y = 0;
  };
  /// The box for box_deflection_m that covers cells first_i..last_i x
  /// first_j..last_j (inclusive): sides rounded up to sizes FFTW transforms
  /// fast (2^k x 4, 5, 6 or 7), kept inside the grid; none where its product
  /// would cost more than about 4/5 of the whole grid's.
  std::optional<CellBox> product_box(int first_i, int last_i, int first_j, int last_j) const;

  /// The deflection [m] on `box`'s cells under the pressure [Pa] on the same
  /// cells (the field elsewhere taken as zero), written into those cells of
  /// `deflection` (nx x ny; the others untouched): the product on the box's
  /// own padded grid, for a field known to vanish off the box. A box size is
  /// planned on first use and kept.
  void box_deflection_m(const Eigen::ArrayXXd& pressure_Pa, const CellBox& box, Eigen::ArrayXXd& deflection) const;

  /// The preconditioner of an iterative solver: a pressure [Pa] (nx x ny)
  /// that gives about this deflection [m] (nx x ny), by the inverse of K's
  /// symbol at wavenumbers well below the cells' (E* |k| / 2, |k| that of
  /// the 5-point Laplacian) on the grid taken as periodic (no padding: one
  /// unpadded r2c/c2r pair, about a third of a product's work). Symmetric
  /// and positive definite on fields of zero mean, which is all a
  /// preconditioner needs; not K's inverse (near the contact's edge above
  /// all), so never a result on its own.
  void approximate_pressure_Pa(const Eigen::ArrayXXd& deflection_m, Eigen::ArrayXXd& pressure_Pa) const;

  /// The same on `box`'s cells alone (the box's grid taken as periodic),
  /// written into those cells of `pressure` (nx x ny; the others untouched).
  void box_approximate_pressure_Pa(const Eigen::ArrayXXd& deflection_m, const CellBox& box,
                                   Eigen::ArrayXXd& pressure_Pa) const;

  /// approximate_pressure_Pa's diagonal [Pa/m]: the pressure on a cell for
  /// a unit deflection of that cell alone.
  double preconditioner_diagonal_Pa_per_m() const { return preconditioner_diagonal_Pa_per_m_; }

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double cell_x_m() const { return cell_x_m_; }
  double cell_y_m() const { return cell_y_m_; }
  double combined_modulus_Pa() const { return combined_modulus_Pa_; }

 private:
  struct Fft;  // FFTW's plans and buffers
  struct BoxProduct;  // a box's convolution and its fields
  BoxProduct& box_product(const CellBox& box) const;  // made on first use
  using FieldMap = void (HalfSpaceConvolution::*)(const Eigen::ArrayXXd&, Eigen::ArrayXXd&) const;
  /// `field_map` on the box's own grid, from and into the box's cells of the grid's fields.
  void on_box(const Eigen::ArrayXXd& in, const CellBox& box, Eigen::ArrayXXd& out, FieldMap field_map) const;
  HalfSpaceConvolution(int nx, int ny, double cell_x_m, double cell_y_m, double combined_modulus_Pa,
                       Eigen::ArrayXXd influence_m_per_Pa);
  int nx_, ny_;
  double cell_x_m_, cell_y_m_, combined_modulus_Pa_;
  std::unique_ptr<Fft> fft_;
  Eigen::ArrayXXd influence_m_per_Pa_;  ///< (2 nx - 1) x (2 ny - 1), offset (0, 0) at (nx - 1, ny - 1)
  int direct_cells_per_product_ = 0;
  double preconditioner_diagonal_Pa_per_m_ = 0.0;
  mutable std::map<std::pair<int, int>, std::unique_ptr<BoxProduct>> boxes_;  ///< by (cells_x, cells_y)
};

}  // namespace railjoint
