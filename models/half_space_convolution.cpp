#include "models/half_space_convolution.h"

#include <mutex>
#include <new>
#include <stdexcept>

#include <fftw3.h>

#include "models/half_space_influence.h"

namespace railjoint {

namespace {
// FFTW's planner is not thread-safe (its execution is): sweeps solve on
// several threads, so plans are made one at a time.
std::mutex& planner_mutex() {
  static std::mutex mutex;
  return mutex;
}
}  // namespace

struct HalfSpaceConvolution::Fft {
  // The padded field is 2 nx x 2 ny, x fastest; FFTW's row-major dims are
  // therefore (2 ny, 2 nx) and its half-spectrum (2 ny) x (nx + 1).
  int px, py, spectrum_size;
  double* real = nullptr;
  fftw_complex* spectrum = nullptr;
  fftw_complex* kernel = nullptr;  // transform of the influence coefficients, divided by px * py
  fftw_plan forward = nullptr, backward = nullptr;

  Fft(int nx, int ny) : px(2 * nx), py(2 * ny), spectrum_size(2 * ny * (nx + 1)) {
    real = fftw_alloc_real(static_cast<std::size_t>(px) * py);
    spectrum = fftw_alloc_complex(spectrum_size);
    kernel = fftw_alloc_complex(spectrum_size);
    if (real == nullptr || spectrum == nullptr || kernel == nullptr) {
      release();
      throw std::bad_alloc();
    }
    const std::lock_guard lock(planner_mutex());
    forward = fftw_plan_dft_r2c_2d(py, px, real, spectrum, FFTW_ESTIMATE);
    backward = fftw_plan_dft_c2r_2d(py, px, spectrum, real, FFTW_ESTIMATE);
  }
  ~Fft() { release(); }
  void release() {
    {
      const std::lock_guard lock(planner_mutex());
      if (forward != nullptr) fftw_destroy_plan(forward);
      if (backward != nullptr) fftw_destroy_plan(backward);
    }
    fftw_free(real);
    fftw_free(spectrum);
    fftw_free(kernel);
  }
};

HalfSpaceConvolution::HalfSpaceConvolution(int nx, int ny, double cell_x_m, double cell_y_m,
                                           double combined_modulus_Pa)
    : nx_(nx),
      ny_(ny),
      cell_x_m_(cell_x_m),
      cell_y_m_(cell_y_m),
      combined_modulus_Pa_(combined_modulus_Pa),
      fft_(std::make_unique<Fft>(nx, ny)) {
  const Eigen::ArrayXXd k = influence_coefficients_m_per_Pa(nx, ny, cell_x_m, cell_y_m, combined_modulus_Pa);
  const int px = fft_->px;
  const int py = fft_->py;
  // Offsets 0..n-1 at the front, -(n-1)..-1 wrapped to the back; the middle
  // row and column (offset n) stay 0: a padded product never reaches them.
  Eigen::Map<Eigen::ArrayXXd> padded(fft_->real, px, py);
  padded.setZero();
  for (int j = -(ny - 1); j < ny; ++j) {
    for (int i = -(nx - 1); i < nx; ++i) {
      padded((i + px) % px, (j + py) % py) = k(nx - 1 + i, ny - 1 + j);
    }
  }
  fftw_execute_dft_r2c(fft_->forward, fft_->real, fft_->kernel);
  const double normalisation = 1.0 / (static_cast<double>(px) * py);
  for (int n = 0; n < fft_->spectrum_size; ++n) {
    fft_->kernel[n][0] *= normalisation;
    fft_->kernel[n][1] *= normalisation;
  }
}

HalfSpaceConvolution::~HalfSpaceConvolution() = default;

Eigen::ArrayXXd HalfSpaceConvolution::deflection_m(const Eigen::ArrayXXd& pressure_Pa) const {
  // The plans' own buffers: one convolution object per thread.
  Eigen::Map<Eigen::ArrayXXd> padded(fft_->real, fft_->px, fft_->py);
  padded.setZero();
  padded.topLeftCorner(nx_, ny_) = pressure_Pa;
  fftw_execute(fft_->forward);
  for (int n = 0; n < fft_->spectrum_size; ++n) {
    const double re = fft_->spectrum[n][0] * fft_->kernel[n][0] - fft_->spectrum[n][1] * fft_->kernel[n][1];
    const double im = fft_->spectrum[n][0] * fft_->kernel[n][1] + fft_->spectrum[n][1] * fft_->kernel[n][0];
    fft_->spectrum[n][0] = re;
    fft_->spectrum[n][1] = im;
  }
  fftw_execute(fft_->backward);
  return padded.topLeftCorner(nx_, ny_);
}

}  // namespace railjoint
