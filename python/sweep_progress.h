#pragma once
// The progress bar of railjoint.sweep(progress=True): written to Python's
// sys.stderr (a terminal, or a notebook's cell), redrawn in place with the
// count, the rate and the time left. The CLI's bar (support/
// progress_meter.h, whose line this draws) writes to the process's stderr, which a notebook does not
// show. Called with the GIL held.

#include <chrono>
#include <cstdint>
#include <string>

namespace railjoint::python {

class SweepProgressBar {
 public:
  explicit SweepProgressBar(std::string label);
  /// Redraws at most five times a second, and always when done == total.
  void show(std::uint64_t done, std::uint64_t total);
  /// Ends the bar's line.
  void finish();

 private:
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;
  bool drawn_ = false;
};

}  // namespace railjoint::python
