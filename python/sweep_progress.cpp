#include "sweep_progress.h"

#include <cstdio>

#include <pybind11/pybind11.h>

#include "support/progress_meter.h"

namespace py = pybind11;

namespace railjoint::python {

namespace {

constexpr auto kRedrawPeriod = std::chrono::milliseconds(200);

}  // namespace

SweepProgressBar::SweepProgressBar(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()), last_(start_) {}

void SweepProgressBar::show(std::uint64_t done, std::uint64_t total) {
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && done < total && now - last_ < kRedrawPeriod) return;
  last_ = now;
  drawn_ = true;
  const double elapsed_s = std::chrono::duration<double>(now - start_).count();
  // Trailing blanks, not the terminal's erase code: a notebook cell shows no escape codes.
  const std::string line = "\r" + progress_bar_text(label_, done, total, elapsed_s, done == total) + "   ";
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
