#include "sweep_progress.h"

#include <cstdio>

#include <pybind11/pybind11.h>

#include "scenes/sweeps/progress_meter.h"

namespace py = pybind11;

namespace railjoint::python {

namespace {

constexpr auto kRedrawPeriod = std::chrono::milliseconds(200);
constexpr int kBarWidth = 30;

}  // namespace

SweepProgressBar::SweepProgressBar(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()), last_(start_) {}

void SweepProgressBar::show(std::uint64_t done, std::uint64_t total) {
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && done < total && now - last_ < kRedrawPeriod) return;
  last_ = now;
  drawn_ = true;
  const double elapsed_s = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed_s > 0 ? static_cast<double>(done) / elapsed_s : 0.0;
  const double fraction = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
  std::string bar(kBarWidth, ' ');
  for (int i = 0; i < static_cast<int>(fraction * kBarWidth) && i < kBarWidth; ++i) bar[static_cast<std::size_t>(i)] = '#';
  const std::string left = done == total ? "in " + duration_text(elapsed_s)
                                         : (rate > 0 ? duration_text(static_cast<double>(total - done) / rate) + " left" : "");
  char line[256];
  std::snprintf(line, sizeof line, "\r%s [%s] %llu/%llu %3.0f %%  %.3g cases/s  %s   ", label_.c_str(), bar.c_str(),
                static_cast<unsigned long long>(done), static_cast<unsigned long long>(total), 100.0 * fraction, rate,
                left.c_str());
  const py::object stderr_ = py::module_::import("sys").attr("stderr");
  if (stderr_.is_none()) return;  // no stream to draw on (pythonw, a closed console): no bar, as print() does
  stderr_.attr("write")(line);
  stderr_.attr("flush")();
}

void SweepProgressBar::finish() {
  if (!drawn_) return;
  const py::object stderr_ = py::module_::import("sys").attr("stderr");
  if (stderr_.is_none()) return;
  stderr_.attr("write")("\n");
  stderr_.attr("flush")();
}

}  // namespace railjoint::python
