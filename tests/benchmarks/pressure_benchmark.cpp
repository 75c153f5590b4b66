// Speed of the local contact-pressure model (models/pressure_traversal.h) on
// table 6.1: a 1000-step exact traversal (target < 1 ms), its summary (the
// refined maxima and the five points), the figure-6.5/6.6 sweep over 100
// junction angles (target < 0.1 s), and the thesis's polygon mode through
// Boost.Geometry for comparison. The boundary-element contact solver
// (models/normal_contact_solver.h): one elastic solve of Hertz's
// crossed cylinders (the wheel on a 300 mm crown, 112.5 kN) on n x n cells
// over 1.25 times the patch's axes, n = 64..512 (target: 128 x 128 within 20 ms),
// preconditioned (the default) and plain.

#include <numbers>
#include <vector>

#include <benchmark/benchmark.h>

#include "models/half_space_influence.h"
#include "models/normal_contact_solver.h"
#include "models/pressure_traversal.h"

namespace {

using namespace railjoint;

PressureInputs table_6_1(PatchShape shape = PatchShape::ellipse) {
  PressureInputs in;
  in.patch = ContactPatch{shape, 0.016, 0.012, 100};
  in.gap = EndPostGap{0.006, std::numbers::pi / 6.0};
  in.steps = 1000;
  return in;
}

void BM_ExactTraversal1000Steps(benchmark::State& state) {
  const PressureInputs in = table_6_1();
  for (auto _ : state) benchmark::DoNotOptimize(pressure_traversal(in));
}
BENCHMARK(BM_ExactTraversal1000Steps)->Unit(benchmark::kMicrosecond);

void BM_ExactTraversalAndSummary(benchmark::State& state) {
  const PressureInputs in = table_6_1();
  for (auto _ : state) {
    const auto traversal = pressure_traversal(in);
    benchmark::DoNotOptimize(summarize_pressure(in, traversal));
  }
}
BENCHMARK(BM_ExactTraversalAndSummary)->Unit(benchmark::kMicrosecond);

void BM_ThetaSweep100Angles(benchmark::State& state) {
  const PressureInputs in = table_6_1();
  for (auto _ : state) benchmark::DoNotOptimize(theta_sweep(in, 1.0, 90.0, 100));
}
BENCHMARK(BM_ThetaSweep100Angles)->Unit(benchmark::kMillisecond);

void BM_PolygonTraversal1000Steps(benchmark::State& state) {
  const PressureInputs in = table_6_1(PatchShape::polygon);
  for (auto _ : state) benchmark::DoNotOptimize(pressure_traversal(in));
}
BENCHMARK(BM_PolygonTraversal1000Steps)->Unit(benchmark::kMillisecond);

void contact_solve(benchmark::State& state, bool preconditioned) {
  const int n = static_cast<int>(state.range(0));
  // Hertz for A = 1/(2 x 0.475), B = 1/(2 x 0.3), 112.5 kN: semi-axes 7.70 x 5.72 mm.
  const double A = 1.0 / (2 * 0.475);
  const double B = 1.0 / (2 * 0.3);
  const double cell_x = 1.25 * 2 * 7.70e-3 / n;
  const double cell_y = 1.25 * 2 * 5.72e-3 / n;
  NormalContactProblem problem;
  problem.gap_m.resize(n, n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = (i - n / 2) * cell_x;
      const double y = (j - n / 2) * cell_y;
      problem.gap_m(i, j) = A * x * x + B * y * y;
    }
  }
  problem.normal_force_N = 112.5e3;
  problem.preconditioned = preconditioned;
  const HalfSpaceConvolution convolution(n, n, cell_x, cell_y, combined_modulus_Pa(210e9, 0.3, 210e9, 0.3));
  int iterations = 0;
  for (auto _ : state) {
    const NormalContactSolution solution = solve_normal_contact(problem, convolution);
    iterations = solution.iterations;
    benchmark::DoNotOptimize(solution.max_pressure_Pa);
  }
  state.counters["iterations"] = iterations;
  state.SetComplexityN(static_cast<int64_t>(n) * n);
}
void BM_ElasticContactSolve(benchmark::State& state) { contact_solve(state, true); }
// Polonsky and Keer's iteration without the preconditioner, for comparison.
void BM_PlainContactSolve(benchmark::State& state) { contact_solve(state, false); }
BENCHMARK(BM_ElasticContactSolve)->RangeMultiplier(2)->Range(64, 512)->Unit(benchmark::kMillisecond)->Complexity(benchmark::oNLogN);
BENCHMARK(BM_PlainContactSolve)->RangeMultiplier(2)->Range(64, 512)->Unit(benchmark::kMillisecond);

// What sets HalfSpaceConvolution::direct_cells_per_product(): one FFT
// product on n x n cells against the direct sum of a single cell's
// deflection over the grid (the solver's correction for cells a step moved).
void BM_ConvolutionProduct(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const HalfSpaceConvolution convolution(n, n, 1e-4, 1e-4, 115e9);
  const Eigen::ArrayXXd p = Eigen::ArrayXXd::Constant(n, n, 1e9);
  Eigen::ArrayXXd u(n, n);
  for (auto _ : state) {
    convolution.deflection_m(p, u);
    benchmark::DoNotOptimize(u.data());
  }
  state.counters["direct_cells_per_product"] = convolution.direct_cells_per_product();
}
BENCHMARK(BM_ConvolutionProduct)->RangeMultiplier(2)->Range(64, 256)->Unit(benchmark::kMicrosecond);

void BM_DirectCellDeflection(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const HalfSpaceConvolution convolution(n, n, 1e-4, 1e-4, 115e9);
  const std::vector<Eigen::Index> cells = {static_cast<Eigen::Index>(n) * n / 2 + n / 3};
  const std::vector<double> pressures_Pa = {1e9};
  Eigen::ArrayXXd u = Eigen::ArrayXXd::Zero(n, n);
  for (auto _ : state) {
    convolution.add_cell_deflections_m(cells, pressures_Pa, u);
    benchmark::DoNotOptimize(u.data());
  }
}
BENCHMARK(BM_DirectCellDeflection)->RangeMultiplier(2)->Range(64, 256)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
