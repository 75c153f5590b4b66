#pragma once
// Where a force run (elastic_crossing_run.h) steps finer: over the
// impact's pulse each sample's step is split, on an elastic track
// (kTrackRings, force_run_track.h) into steps of at most
// sim.refined_time_step (4 of 1e-6 s at the default 4e-6 s), a damped
// contact's sqrt(1 + alpha) finer there and on the rigid track
// (elastic_crossing_run.cpp); elsewhere one step a sample. The samples stay a fixed step apart (P1's parabola, the low
// pass and the flights of force_peaks.h read them so).
//
// Why (issue 39): velocity Verlet's error on an oscillation of frequency w
// is (w dt)^2 / 24 in its phase. On the lumped track the rail mass rings on
// the Hertz spring after the strike at ~8.5e3 rad/s, and P1 is often not the
// first crest but a later one (the default scene's second, 0.75 ms after the
// first): at 4e-6 s P1 was 7.1e-5 low. Not the sampling (stepped at 0.5e-6 s
// and sampled at 4e-6 s: P1 within 1e-6 of the converged value), nor the
// first crest alone (fine while above half its height: -5.4e-5), but the
// whole ringing up to P1 (fine from 2 % over the static force until the end:
// -1.1e-5) and the steps in which the contact is made (fine from the step
// before: -4.4e-6, the same as every step at 1e-6 s).
//
// The window opens
//  - as a contact is about to be made (its gap, at its rate, closes within
//    the next two steps), and then stays open for `hold_s` unless the force
//    rises first;
//  - while any wheel's contact force is above half its peak so far over the
//    static force (the P1 pulse's own measure, force_peaks.h) and at least
//    kDeparture of the static force above it, or, until it first is, more
//    than kDeparture below the static force (the wheel leaving the incoming
//    rail before the strike: the rail mass rings on its pad meanwhile; a
//    seeded lumped crossing at 75 m/s read P1 1.7e-5 high without);
// and stays open for `hold_s` after the force was last so. Then it
// closes for good: a later hump (P2) is stepped coarse, and only a contact
// made again (a landing) reopens it. The run's `hold_s` is half a period of
// the wheel on the Hertz spring at the static load (2.0 ms on the defaults,
// ~2.7 periods of the lumped rail's ringing: a crest or two below half
// height between two above it stay inside; half of it still held on 20
// seeded crossings, a quarter let one lumped P1 go to 5.3e-5).

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace railjoint {

class PulseWindow {
 public:
  /// The force's departure from the static force that opens the window (a
  /// discrete track's rolling over sleepers moves it by 5e-3 at 50 m/s).
  static constexpr double kDeparture = 0.02;

  /// `static_N`: each wheel's contact force at the run's start; `hold_s`: how
  /// long a contact about to be made keeps the window open without the force
  /// rising, and how long it stays open after the force was last above half
  /// its peak height.
  PulseWindow(std::vector<double> static_N, double hold_s)
      : static_N_(static_N), peak_N_(std::move(static_N)), hold_s_(hold_s) {}

  /// (each wheel's contact force at `time_s`, whether a contact closes within
  /// the next two steps) => whether the next step is taken fine.
  bool fine_after(const std::vector<double>& force_N, bool contact_closing, double time_s) {
    bool above = false;
    bool unloaded = false;
    for (std::size_t k = 0; k < force_N.size() && k < static_N_.size(); ++k) {
      const double S = static_N_[k];
      peak_N_[k] = std::max(peak_N_[k], force_N[k]);
      if (force_N[k] > S + std::max(0.5 * (peak_N_[k] - S), kDeparture * S)) above = true;
      if (force_N[k] < S * (1.0 - kDeparture)) unloaded = true;
    }
    // Unloading counts until the force has first risen (the wheel leaving
    // the incoming rail before the strike; the ringing's troughs after it
    // are the hold's).
    const bool active = above || (unloaded && !risen_);
    if (above) risen_ = true;
    if (contact_closing) {
      opened_at_s_ = time_s;
      state_ = State::armed;
      return true;
    }
    switch (state_) {
      case State::waiting:
        if (!active) return false;
        state_ = State::pulse;
        break;
      case State::armed:
        if (!active) return time_s - opened_at_s_ < hold_s_;
        state_ = State::pulse;
        break;
      case State::pulse:
        break;
      case State::done:
        return false;
    }
    if (active) last_active_s_ = time_s;
    if (time_s - last_active_s_ < hold_s_) return true;
    state_ = State::done;
    return false;
  }

 private:
  enum class State { waiting, armed, pulse, done };
  std::vector<double> static_N_;
  std::vector<double> peak_N_;
  double hold_s_ = 0.0;
  State state_ = State::waiting;
  double opened_at_s_ = 0.0;
  bool risen_ = false;  // the force has been above half its peak height
  double last_active_s_ = 0.0;
};

}  // namespace railjoint
