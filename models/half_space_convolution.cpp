#include "models/half_space_convolution.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <new>
#include <numbers>
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

// A direct-sum cell costs N multiply-adds, an FFT product about
// 4N log2(4N) of them: BM_ConvolutionProduct against BM_DirectCellDeflection
// gave 38 / 62 / 67 cells a product at 64 / 128 / 256 cells a side (0.7-0.95
// of the formula); half of it is taken, so that the direct sum is the cheaper.
constexpr double kDirectOverFft = 0.5;
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
  // The preconditioner's transforms: the unpadded nx x ny grid, periodic
  // (FFTW's r2c layout for the row-major (ny, nx) array: (nx/2 + 1) x ny
  // complex), and its symbol divided by nx * ny.
  int periodic_spectrum_size;
  double* periodic = nullptr;
  fftw_complex* periodic_spectrum = nullptr;
  double* periodic_symbol = nullptr;
  fftw_plan periodic_forward = nullptr, periodic_backward = nullptr;

  Fft(int nx_, int ny_)
      : nx(nx_),
        ny(ny_),
        px(2 * nx_),
        py(2 * ny_),
        spectrum_size((nx_ + 1) * 2 * ny_),
        periodic_spectrum_size((nx_ / 2 + 1) * ny_) {
    const std::size_t reals = static_cast<std::size_t>(px) * ny;
    in = fftw_alloc_real(reals);
    out = fftw_alloc_real(reals);
    half = fftw_alloc_complex(spectrum_size);
    full = fftw_alloc_complex(spectrum_size);
    kernel = fftw_alloc_real(spectrum_size);
    periodic = fftw_alloc_real(static_cast<std::size_t>(nx) * ny);
    periodic_spectrum = fftw_alloc_complex(periodic_spectrum_size);
    periodic_symbol = fftw_alloc_real(periodic_spectrum_size);
    if (in == nullptr || out == nullptr || half == nullptr || full == nullptr || kernel == nullptr ||
        periodic == nullptr || periodic_spectrum == nullptr || periodic_symbol == nullptr) {
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
      periodic_forward = fftw_plan_dft_r2c_2d(ny, nx, periodic, periodic_spectrum, kPlanning);
      periodic_backward = fftw_plan_dft_c2r_2d(ny, nx, periodic_spectrum, periodic, kPlanning);
    }
    if (forward_x == nullptr || forward_y == nullptr || backward_y == nullptr || backward_x == nullptr ||
        periodic_forward == nullptr || periodic_backward == nullptr) {
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
      for (fftw_plan plan : {forward_x, forward_y, backward_y, backward_x, periodic_forward, periodic_backward}) {
        if (plan != nullptr) fftw_destroy_plan(plan);
      }
    }
    fftw_free(in);
    fftw_free(out);
    fftw_free(half);
    fftw_free(full);
    fftw_free(kernel);
    fftw_free(periodic);
    fftw_free(periodic_spectrum);
    fftw_free(periodic_symbol);
  }
};

struct HalfSpaceConvolution::BoxProduct {
  std::unique_ptr<HalfSpaceConvolution> convolution;
  Eigen::ArrayXXd in, out;  // the box's cells: a pressure and its deflection, or the reverse
};

HalfSpaceConvolution::HalfSpaceConvolution(int nx, int ny, double cell_x_m, double cell_y_m,
                                           double combined_modulus_Pa)
    : HalfSpaceConvolution(nx, ny, cell_x_m, cell_y_m, combined_modulus_Pa,
                           influence_coefficients_m_per_Pa(nx, ny, cell_x_m, cell_y_m, combined_modulus_Pa)) {}

HalfSpaceConvolution::HalfSpaceConvolution(int nx, int ny, double cell_x_m, double cell_y_m,
                                           double combined_modulus_Pa, Eigen::ArrayXXd influence_m_per_Pa)
    : nx_(nx),
      ny_(ny),
      cell_x_m_(cell_x_m),
      cell_y_m_(cell_y_m),
      combined_modulus_Pa_(combined_modulus_Pa),
      fft_(std::make_unique<Fft>(nx, ny)),
      influence_m_per_Pa_(std::move(influence_m_per_Pa)) {
  const Eigen::ArrayXXd& k = influence_m_per_Pa_;
  {
    const double padded = 4.0 * nx * ny;
    direct_cells_per_product_ = static_cast<int>(kDirectOverFft * padded * std::log2(padded) / (nx * ny));
  }
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

  // The preconditioner's symbol: K's is 2 / (E* |k|) for wavenumbers well
  // below the cells' (Johnson 1985, the Boussinesq kernel 1/(pi E* r)
  // transformed), so its inverse is E* |k| / 2, with |k|^2 the symbol of the
  // 5-point Laplacian on the cells (2 sin(k h / 2) / h per direction): a
  // first-order operator with no cost beyond one unpadded transform pair.
  const int periodic_columns = nx / 2 + 1;
  const double periodic_normalisation = 1.0 / (static_cast<double>(nx) * ny);
  for (int jy = 0; jy < ny; ++jy) {
    const double ky = 2.0 / cell_y_m * std::sin(std::numbers::pi * jy / ny);
    for (int ix = 0; ix < periodic_columns; ++ix) {
      const double kx = 2.0 / cell_x_m * std::sin(std::numbers::pi * ix / nx);
      fft_->periodic_symbol[jy * periodic_columns + ix] =
          0.5 * combined_modulus_Pa * std::sqrt(kx * kx + ky * ky) * periodic_normalisation;
    }
  }
  // Its diagonal: the pressure it gives a cell for a unit deflection of that
  // cell alone (the same for every cell of a periodic grid).
  Eigen::ArrayXXd unit = Eigen::ArrayXXd::Zero(nx, ny);
  unit(0, 0) = 1.0;
  Eigen::ArrayXXd response(nx, ny);
  approximate_pressure_Pa(unit, response);
  preconditioner_diagonal_Pa_per_m_ = response(0, 0);
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

void HalfSpaceConvolution::approximate_pressure_Pa(const Eigen::ArrayXXd& deflection_m, Eigen::ArrayXXd& pressure_Pa) const {
  Fft& f = *fft_;
  Eigen::Map<Eigen::ArrayXXd>(f.periodic, nx_, ny_) = deflection_m;
  fftw_execute(f.periodic_forward);
  for (int n = 0; n < f.periodic_spectrum_size; ++n) {
    f.periodic_spectrum[n][0] *= f.periodic_symbol[n];
    f.periodic_spectrum[n][1] *= f.periodic_symbol[n];
  }
  fftw_execute(f.periodic_backward);
  pressure_Pa.resize(nx_, ny_);
  pressure_Pa = Eigen::Map<const Eigen::ArrayXXd>(f.periodic, nx_, ny_);
}

namespace {
// The smallest n >= cells of the form 2^k x 4, 5, 6 or 7: its padded
// transforms (2n) have no prime factor above 7.
int fast_size(int cells) {
  for (int power = 1;; power *= 2) {
    for (int factor : {4, 5, 6, 7}) {
      if (power * factor >= cells) return power * factor;
    }
  }
}
}  // namespace

std::optional<HalfSpaceConvolution::CellBox> HalfSpaceConvolution::product_box(int first_i, int last_i, int first_j,
                                                                               int last_j) const {
  const int cells_x = fast_size(last_i - first_i + 1);
  const int cells_y = fast_size(last_j - first_j + 1);
  // Its transforms cost about (cells_x cells_y) / (nx ny) of the grid's;
  // 4/5 leaves room for the sizes' less efficient factors (at 128 x 128 a
  // 112 x 112 box made the benchmark's solve 10 % faster).
  if (cells_x > nx_ || cells_y > ny_ || 5.0 * cells_x * cells_y > 4.0 * nx_ * ny_) return std::nullopt;
  CellBox box;
  box.cells_x = cells_x;
  box.cells_y = cells_y;
  box.first_i = std::min(first_i, nx_ - cells_x);
  box.first_j = std::min(first_j, ny_ - cells_y);
  return box;
}

HalfSpaceConvolution::BoxProduct& HalfSpaceConvolution::box_product(const CellBox& box) const {
  std::unique_ptr<BoxProduct>& product = boxes_[{box.cells_x, box.cells_y}];
  if (!product) {
    // Offsets up to the box's size: the middle of the grid's own coefficients.
    product = std::make_unique<BoxProduct>();
    product->convolution.reset(new HalfSpaceConvolution(
        box.cells_x, box.cells_y, cell_x_m_, cell_y_m_, combined_modulus_Pa_,
        influence_m_per_Pa_.block(nx_ - box.cells_x, ny_ - box.cells_y, 2 * box.cells_x - 1, 2 * box.cells_y - 1)));
  }
  return *product;
}

void HalfSpaceConvolution::box_deflection_m(const Eigen::ArrayXXd& pressure_Pa, const CellBox& box,
                                            Eigen::ArrayXXd& deflection) const {
  on_box(pressure_Pa, box, deflection, &HalfSpaceConvolution::deflection_m);
}

void HalfSpaceConvolution::box_approximate_pressure_Pa(const Eigen::ArrayXXd& deflection_m, const CellBox& box,
                                                       Eigen::ArrayXXd& pressure_Pa) const {
  on_box(deflection_m, box, pressure_Pa, &HalfSpaceConvolution::approximate_pressure_Pa);
}

void HalfSpaceConvolution::on_box(const Eigen::ArrayXXd& in, const CellBox& box, Eigen::ArrayXXd& out,
                                  FieldMap field_map) const {
  BoxProduct& product = box_product(box);
  product.in = in.block(box.first_i, box.first_j, box.cells_x, box.cells_y);
  (product.convolution.get()->*field_map)(product.in, product.out);
  out.block(box.first_i, box.first_j, box.cells_x, box.cells_y) = product.out;
}

void HalfSpaceConvolution::add_cell_deflections_m(const std::vector<Eigen::Index>& cells,
                                                  const std::vector<double>& pressures_Pa,
                                                  Eigen::ArrayXXd& deflection) const {
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const Eigen::Index ic = cells[c] % nx_;
    const Eigen::Index jc = cells[c] / nx_;
    const double p = pressures_Pa[c];
    // u(i, j) += p K(i - ic, j - jc): the rows nx-1-ic .. 2nx-2-ic of K's columns.
    for (Eigen::Index j = 0; j < ny_; ++j) {
      deflection.col(j) += p * influence_m_per_Pa_.col(ny_ - 1 + j - jc).segment(nx_ - 1 - ic, nx_);
    }
  }
}

}  // namespace railjoint
