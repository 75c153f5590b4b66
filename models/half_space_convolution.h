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

#include <memory>

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

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double cell_x_m() const { return cell_x_m_; }
  double cell_y_m() const { return cell_y_m_; }
  double combined_modulus_Pa() const { return combined_modulus_Pa_; }

 private:
  struct Fft;  // FFTW's plans and buffers
  int nx_, ny_;
  double cell_x_m_, cell_y_m_, combined_modulus_Pa_;
  std::unique_ptr<Fft> fft_;
};

}  // namespace railjoint
