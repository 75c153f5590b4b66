#pragma once
// A way out of a long run for a caller that must stop it early (the Python
// module: Ctrl-C in simulate() raises KeyboardInterrupt within a second, not
// when the run ends). The caller installs a check on its own thread for the
// run's duration; the stepping loops (and the analytic time history's
// sample loop, models/) call poll_run_interrupt() every step,
// which calls the check every kRunInterruptPollSteps steps. The check ends
// the run by throwing; everything in a run is owned (RAII), so it unwinds.
// No check installed (the CLI, the tests): a counter and a branch per step.

#include <functional>
#include <utility>

namespace railjoint {

/// Steps between checks: about a millisecond of a rigid run's stepping, far
/// less of a force run's.
inline constexpr int kRunInterruptPollSteps = 1024;

namespace detail {
inline thread_local const std::function<void()>* run_interrupt_check = nullptr;
}  // namespace detail

/// Installs `check` on this thread while it lives (not nested: one run at a time per thread).
class RunInterruptCheck {
 public:
  explicit RunInterruptCheck(std::function<void()> check) : check_(std::move(check)) {
    detail::run_interrupt_check = &check_;
  }
  ~RunInterruptCheck() { detail::run_interrupt_check = nullptr; }
  RunInterruptCheck(const RunInterruptCheck&) = delete;
  RunInterruptCheck& operator=(const RunInterruptCheck&) = delete;

 private:
  std::function<void()> check_;
};

/// Called by a stepping loop with its step count: every kRunInterruptPollSteps
/// steps, this thread's check, which may throw to end the run.
inline void poll_run_interrupt(int steps) {
  if (steps % kRunInterruptPollSteps == 0 && detail::run_interrupt_check != nullptr) (*detail::run_interrupt_check)();
}

}  // namespace railjoint
