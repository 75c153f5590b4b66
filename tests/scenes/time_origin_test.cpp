// The outputs' time origin (sim/time_origin.h): the run time at
// which the wheel centre passes a position, between samples and beyond them.

#include <gtest/gtest.h>

#include "sim/time_origin.h"

namespace railjoint {
namespace {

WheelSample sample(double t_s, double x_m, double xdot_m_per_s) {
  WheelSample s;
  s.time_s = t_s;
  s.centre_m.x() = x_m;
  s.velocity_m_per_s.x() = xdot_m_per_s;
  return s;
}

// A wheel slowing down, as in the inertial mode: 2 m in the first second,
// 1 m in the next. Linear between samples: x = 2.5 m half way through the second.
TEST(TimeOrigin, InterpolatesBetweenTheSamplesAroundThePosition) {
  const std::vector<WheelSample> samples = {sample(0.0, 0.0, 2.0), sample(1.0, 2.0, 1.5), sample(2.0, 3.0, 1.0)};
  EXPECT_DOUBLE_EQ(passage_time_s(samples, 2.5), 1.5);
  EXPECT_DOUBLE_EQ(passage_time_s(samples, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(passage_time_s(samples, 2.0), 1.0);
}

// A position the run does not reach is carried on at the nearest sample's speed.
TEST(TimeOrigin, CarriesTheEndSamplesSpeedBeyondTheRun) {
  const std::vector<WheelSample> samples = {sample(0.0, 0.0, 2.0), sample(1.0, 2.0, 1.5), sample(2.0, 3.0, 1.0)};
  EXPECT_DOUBLE_EQ(passage_time_s(samples, -1.0), -0.5);
  EXPECT_DOUBLE_EQ(passage_time_s(samples, 4.0), 3.0);
}

}  // namespace
}  // namespace railjoint
