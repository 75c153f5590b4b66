#pragma once
// Progress of a long run of cases on stderr, from a thread of its own: on a
// terminal a bar redrawn in place with the count, the rate and the time
// left; in a log (stderr not a terminal) a plain line every few seconds and
// one at the end. Workers only add to an atomic counter.

#include <atomic>
#include <chrono>
#include <condition_variable>
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

}  // namespace railjoint
