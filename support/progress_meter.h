#pragma once
// Progress on stderr, the one meter of the CLI and the Python module.
// ProgressMeter: a long run of cases, from a thread of its own: on a terminal
// a bar redrawn in place with the count, the rate and the time left; in a log
// (stderr not a terminal) a plain line every few seconds and one at the end.
// Workers only add to an atomic counter. progress_bar_text() is that bar's
// line, which the Python module draws on sys.stderr. show_progress(): a few
// named steps ("[2/5] figure 4.5").

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace railjoint {

class ProgressMeter {
 public:
  /// Starts showing `label` and 0 of `total`. `enabled` false: shows nothing
  /// (the other MPI ranks, quiet callers).
  ProgressMeter(std::string label, std::uint64_t total, bool enabled = true);
  /// Stops, and leaves the final count on its own line.
  ~ProgressMeter();
  ProgressMeter(const ProgressMeter&) = delete;
  ProgressMeter& operator=(const ProgressMeter&) = delete;

  void add(std::uint64_t done) { done_.fetch_add(done, std::memory_order_relaxed); }
  std::uint64_t done() const { return done_.load(std::memory_order_relaxed); }

 private:
  void show(bool final);
  void loop();

  std::string label_;
  std::uint64_t total_;
  bool enabled_;
  bool terminal_;
  std::atomic<std::uint64_t> done_{0};
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_line_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

/// "1:02:03" / "2:03" / "45 s".
std::string duration_text(double seconds);

/// The bar's line, without a carriage return: "label [#####     ] 120/240  50 %
/// 448 cases/s  1 s left"; `final`: "in 1 s" for the time left.
std::string progress_bar_text(const std::string& label, std::uint64_t done, std::uint64_t total, double elapsed_s,
                              bool final);

/// Step i of n, "[i+1/n] label", on stderr: rewritten in place on a
/// terminal, one line per step in a log (stderr not a terminal).
void show_progress(std::size_t i, std::size_t n, const std::string& label);

/// Clears the step line on a terminal (nothing to do in a log).
void end_progress();

}  // namespace railjoint
