#include "models/half_space_convolution.h"

#include <algorithm>
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

// FFTW_ESTIMATE: plans in microseconds from FFTW's cost model. FFTW_MEASURE
// was timed too (tests/benchmarks/pressure_benchmark.cpp) and is not used:
// see docs/rail-end-contact.md, "Cost".
constexpr unsigned kPlanning = FFTW_ESTIMATE;
}  // namespace

// Layouts (x fastest, as Eigen's column-major nx x ny fields):
//   in   px x ny reals: the pressure in rows 0..nx-1, rows nx..px-1 zero for good;
//   half (nx + 1) x py complex: the x-transform of `in` in columns 0..ny-1,
//        columns ny..py-1 zero for good (the padding in y);
//   full (nx + 1) x py complex: the 2D half-spectrum, FFTW's r2c layout for
//        the row-major (py, px) array, so the kernel's 2D r2c matches it;
//   out  px x ny reals: the deflection in rows 0..nx-1 (the rest is the
//        circular wrap, thrown away).
struct HalfSpaceConvolution::Fft {
  int nx, ny, px, py, spectrum_size;
  double* in = nullptr;
  double* out = nullptr;
  fftw_complex* half = nullptr;
  fftw_complex* full = nullptr;
  // The influence coefficients' transform divided by px * py, made once: K
  // is even in x and in y, so the transform is real.
  double* kernel = nullptr;
  fftw_plan forward_x = nullptr, forward_y = nullptr, backward_y = nullptr, backward_x = nullptr;

  Fft(int nx_, int ny_) : nx(nx_), ny(ny_), px(2 * nx_), py(2 * ny_), spectrum_size((nx_ + 1) * 2 * ny_) {
    const std::size_t reals = static_cast<std::size_t>(px) * ny;
    in = fftw_alloc_real(reals);
    out = fftw_alloc_real(reals);
    half = fftw_alloc_complex(spectrum_size);
    full = fftw_alloc_complex(spectrum_size);
    kernel = fftw_alloc_real(spectrum_size);
    if (in == nullptr || out == nullptr || half == nullptr || full == nullptr || kernel == nullptr) {
      release();
      throw std::bad_alloc();
    }
    const int columns = nx + 1;
    {
      const std::lock_guard lock(planner_mutex());
      // x: ny real columns of length px -> ny half-spectrum columns.
      forward_x = fftw_plan_many_dft_r2c(1, &px, ny, in, nullptr, 1, px, half, nullptr, 1, columns, kPlanning);
      // y: nx + 1 rows of length py, stride nx + 1; `half` must keep its zeros.
      forward_y = fftw_plan_many_dft(1, &py, columns, half, nullptr, columns, 1, full, nullptr, columns, 1,
                                     FFTW_FORWARD, kPlanning | FFTW_PRESERVE_INPUT);
      backward_y = fftw_plan_many_dft(1, &py, columns, full, nullptr, columns, 1, full, nullptr, columns, 1,
                                      FFTW_BACKWARD, kPlanning);
      // x back: only the ny columns returned.
      backward_x = fftw_plan_many_dft_c2r(1, &px, ny, full, nullptr, 1, columns, out, nullptr, 1, px, kPlanning);
    }
    if (forward_x == nullptr || forward_y == nullptr || backward_y == nullptr || backward_x == nullptr) {
      release();
      throw std::runtime_error("HalfSpaceConvolution: FFTW could not plan the transforms");
    }
    // Planning may write the buffers: the zeros that stay are set after it.
    std::fill(in, in + reals, 0.0);
    for (int n = 0; n < spectrum_size; ++n) half[n][0] = half[n][1] = 0.0;
  }
  ~Fft() { release(); }
  void release() {
    {
      const std::lock_guard lock(planner_mutex());
      for (fftw_plan plan : {forward_x, forward_y, backward_y, backward_x}) {
        if (plan != nullptr) fftw_destroy_plan(plan);
      }
    }
    fftw_free(in);
    fftw_free(out);
    fftw_free(half);
    fftw_free(full);
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
  // The kernel fills the whole padded grid: one 2D transform, made once,
  // into `full` (scratch between products).
  // Offsets 0..n-1 at the front, -(n-1)..-1 wrapped to the back; the middle
  // row and column (offset n) stay 0: a padded product never reaches them.
  double* padded_data = fftw_alloc_real(static_cast<std::size_t>(px) * py);
  if (padded_data == nullptr) throw std::bad_alloc();
  fftw_plan plan = nullptr;
  {
    const std::lock_guard lock(planner_mutex());
    plan = fftw_plan_dft_r2c_2d(py, px, padded_data, fft_->full, FFTW_ESTIMATE);
  }
  Eigen::Map<Eigen::ArrayXXd> padded(padded_data, px, py);
  padded.setZero();
  for (int j = -(ny - 1); j < ny; ++j) {
    for (int i = -(nx - 1); i < nx; ++i) {
      padded((i + px) % px, (j + py) % py) = k(nx - 1 + i, ny - 1 + j);
    }
  }
  if (plan == nullptr) {
    fftw_free(padded_data);
    throw std::runtime_error("HalfSpaceConvolution: FFTW could not plan the kernel's transform");
  }
  fftw_execute(plan);
  {
    const std::lock_guard lock(planner_mutex());
    fftw_destroy_plan(plan);
  }
  fftw_free(padded_data);
  const double normalisation = 1.0 / (static_cast<double>(px) * py);
  // The imaginary parts are rounding (some 1e-16 of the real ones): dropped.
  for (int n = 0; n < fft_->spectrum_size; ++n) fft_->kernel[n] = fft_->full[n][0] * normalisation;
}

HalfSpaceConvolution::~HalfSpaceConvolution() = default;

Eigen::ArrayXXd HalfSpaceConvolution::deflection_m(const Eigen::ArrayXXd& pressure_Pa) const {
  Eigen::ArrayXXd deflection(nx_, ny_);
  deflection_m(pressure_Pa, deflection);
  return deflection;
}

void HalfSpaceConvolution::deflection_m(const Eigen::ArrayXXd& pressure_Pa, Eigen::ArrayXXd& deflection) const {
  // The plans' own buffers: one convolution object per thread.
  Fft& f = *fft_;
  Eigen::Map<Eigen::ArrayXXd> in(f.in, f.px, ny_);
  in.topRows(nx_) = pressure_Pa;
  fftw_execute(f.forward_x);
  fftw_execute(f.forward_y);
  for (int n = 0; n < f.spectrum_size; ++n) {
    f.full[n][0] *= f.kernel[n];
    f.full[n][1] *= f.kernel[n];
  }
  fftw_execute(f.backward_y);
  fftw_execute(f.backward_x);
  deflection.resize(nx_, ny_);
  deflection = Eigen::Map<const Eigen::ArrayXXd>(f.out, f.px, ny_).topRows(nx_);
}

}  // namespace railjoint
