// Where a force run steps finer (sim/pulse_window.h), on hand-made force
// histories: the rule as stated there, each case read off by hand.

#include "sim/pulse_window.h"

#include <gtest/gtest.h>

namespace railjoint {
namespace {

constexpr double kStatic_N = 100e3;
constexpr double kHold_s = 1e-3;
constexpr double kStep_s = 1e-4;

TEST(PulseWindow, RollingOnTheLevelOrOverSleepersStaysCoarse) {
  // +-1 % about the static force (a discrete track's sleepers move it by
  // 0.5 % at 50 m/s): below the 2 % departure, nothing opens the window.
  PulseWindow w({kStatic_N}, kHold_s);
  for (int k = 0; k < 100; ++k) {
    const double F = kStatic_N * (1.0 + 0.01 * ((k % 2) ? 1 : -1));
    EXPECT_FALSE(w.fine_after({F}, false, k * kStep_s)) << k;
  }
}

TEST(PulseWindow, AContactAboutToBeMadeOpensItForTheHoldUnlessTheForceRises) {
  PulseWindow w({kStatic_N}, kHold_s);
  EXPECT_TRUE(w.fine_after({kStatic_N}, true, 0.0));
  // The force stays static: open for the hold (1e-3 s) after, then closed.
  EXPECT_TRUE(w.fine_after({kStatic_N}, false, 0.5e-3));
  EXPECT_TRUE(w.fine_after({kStatic_N}, false, 0.99e-3));
  EXPECT_FALSE(w.fine_after({kStatic_N}, false, 1.0e-3));
  EXPECT_FALSE(w.fine_after({kStatic_N}, false, 1.5e-3));
}

TEST(PulseWindow, APulseKeepsItOpenWhileAboveHalfItsHeightAndForTheHoldAfter) {
  PulseWindow w({kStatic_N}, kHold_s);
  // The force rises to 500 kN: above 2 % over static and above half the
  // height so far (it is the peak), so open.
  EXPECT_TRUE(w.fine_after({103e3}, false, 0.0));
  EXPECT_TRUE(w.fine_after({500e3}, false, 0.1e-3));
  // Half height: 100 + 0.5 (500 - 100) = 300 kN. At 301 kN still above.
  EXPECT_TRUE(w.fine_after({301e3}, false, 0.2e-3));
  // Below it from 0.3 ms: open for the hold after the last sample above
  // (0.2 ms), so until 1.2 ms.
  EXPECT_TRUE(w.fine_after({50e3}, false, 0.3e-3));
  // A later crest above half height within the hold (the ringing's next
  // one) restarts it: last above at 0.8 ms, open until 1.8 ms.
  EXPECT_TRUE(w.fine_after({450e3}, false, 0.8e-3));
  EXPECT_TRUE(w.fine_after({200e3}, false, 1.7e-3));
  EXPECT_FALSE(w.fine_after({200e3}, false, 1.9e-3));
  // Closed for good: a later hump above half height (P2) leaves it closed.
  EXPECT_FALSE(w.fine_after({350e3}, false, 5e-3));
  // A contact made again (a landing after a flight) opens it again.
  EXPECT_TRUE(w.fine_after({0.0}, true, 6e-3));
  EXPECT_TRUE(w.fine_after({0.0}, false, 6.5e-3));
}

TEST(PulseWindow, UnloadingBeforeThePulseOpensItButTheRingingsTroughsDoNot) {
  PulseWindow w({kStatic_N}, kHold_s);
  // The wheel leaves the incoming rail: 3 % below static opens the window.
  EXPECT_FALSE(w.fine_after({99e3}, false, 0.0));
  EXPECT_TRUE(w.fine_after({97e3}, false, 0.1e-3));
  EXPECT_TRUE(w.fine_after({0.0}, false, 0.5e-3));
  // The strike: up to 400 kN (half height 250 kN), then a trough at 0 from
  // 0.7 ms. Last above half height at 0.6 ms: open until 1.6 ms, not longer
  // for being unloaded.
  EXPECT_TRUE(w.fine_after({400e3}, false, 0.6e-3));
  EXPECT_TRUE(w.fine_after({0.0}, false, 0.7e-3));
  EXPECT_TRUE(w.fine_after({0.0}, false, 1.5e-3));
  EXPECT_FALSE(w.fine_after({0.0}, false, 1.7e-3));
}

TEST(PulseWindow, AnyWheelOpensIt) {
  // A bogie: the trailing wheel's pulse opens the window as the leading one's.
  PulseWindow w({kStatic_N, kStatic_N}, kHold_s);
  EXPECT_FALSE(w.fine_after({kStatic_N, kStatic_N}, false, 0.0));
  EXPECT_TRUE(w.fine_after({kStatic_N, 400e3}, false, 0.1e-3));
}

}  // namespace
}  // namespace railjoint
