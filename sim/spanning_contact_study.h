#pragma once
// A study's hold on the force run's spanning contact (rail_end_patch_share.h):
// which law spanning_contact applies on this thread, and a trace of what it
// returned, call by call. The merged-patch law is the model; the
// conservative variant exists to measure what the merged law's
// non-conservative work does to P1 and P2 (tests/sim/spanning_law_study.cpp,
// docs/forces.md "What the merged law's own work does to P1 and P2"). Not a
// setting: no scene can choose it. Held by one object at a time per thread;
// nothing changes while none is.

#include <array>
#include <vector>

namespace railjoint {

enum class SpanningLaw { merged, conservative };

/// One call of spanning_contact: its penetrations in, and per rail end the
/// effective penetration, share and Hertz's force at the effective
/// penetration it returned (the force applied is share x that) [m, -, N].
struct SpanningTraceEntry {
  std::array<double, 2> penetration_m{};
  std::array<double, 2> effective_penetration_m{};
  std::array<double, 2> share{};
  std::array<double, 2> hertz_force_N{};
};

/// While it lives, spanning_contact on this thread applies `law` and, given
/// a trace, appends each call's entry to it.
class ScopedSpanningContactStudy {
 public:
  explicit ScopedSpanningContactStudy(SpanningLaw law, std::vector<SpanningTraceEntry>* trace = nullptr);
  ~ScopedSpanningContactStudy();
  ScopedSpanningContactStudy(const ScopedSpanningContactStudy&) = delete;
  ScopedSpanningContactStudy& operator=(const ScopedSpanningContactStudy&) = delete;

 private:
  SpanningLaw law_;
  std::vector<SpanningTraceEntry>* trace_;
  const ScopedSpanningContactStudy* previous_;
  friend struct SpanningContactStudyAccess;
};

}  // namespace railjoint
