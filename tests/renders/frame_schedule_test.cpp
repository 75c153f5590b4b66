// Frame times in simulated time and the interpolated wheel state.

#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "renders/frame_schedule.h"
#include "support/input_error.h"

namespace railjoint {
namespace {

// Samples every 1e-4 s on [0, 0.01] s, the centre moving at 10 m/s along x.
Trajectory straight_run() {
  Trajectory t;
  for (int i = 0; i <= 100; ++i) {
    WheelSample s;
    s.time_s = i * 1e-4;
    s.centre_m = {10.0 * s.time_s, 0.015, 0.475};
    s.spin_angle_rad = 10.0 * s.time_s / 0.475;
    t.samples.push_back(s);
  }
  return t;
}

std::string key_of(const RenderSettings& settings, const Trajectory& trajectory) {
  try {
    frame_window(settings, trajectory);
  } catch (const InputError& error) {
    std::cout << "  " << error.key() << ": " << error.what() << "\n";
    return error.key();
  }
  return "none";
}

TEST(FrameSchedule, WholeNumberOfPeriodsIncludesBothEnds) {
  // 1 ms at 10000 frames per simulated second = 10 periods -> 11 frames at
  // 2.0, 2.1, ..., 3.0 ms.
  RenderSettings s;
  s.fps = 10000;
  s.t_start_s = 0.002;
  s.t_end_s = 0.003;
  const FrameWindow w = frame_window(s, straight_run());
  std::cout << "count " << w.count << ", last frame at " << w.time_s(w.count - 1) << " s\n";
  EXPECT_EQ(w.count, 11);
  EXPECT_NEAR(w.time_s(0), 0.002, 1e-15);
  EXPECT_NEAR(w.time_s(10), 0.003, 1e-15);
}

TEST(FrameSchedule, RoundingOfWindowTimesFpsDoesNotLoseTheLastFrame) {
  // 0.001 * 20000 is 19.999999999999996 in doubles; the window still holds
  // 20 periods, 21 frames.
  RenderSettings s;
  s.fps = 20000;
  s.t_start_s = 0.0;
  s.t_end_s = 0.001;
  EXPECT_EQ(frame_window(s, straight_run()).count, 21);
}

TEST(FrameSchedule, PartialLastPeriodEndsAtTheLastFrameBeforeTheEnd) {
  // 1.25 ms at 10000 fps = 12.5 periods -> frames at 0, 0.1, ..., 1.2 ms: 13.
  RenderSettings s;
  s.fps = 10000;
  s.t_start_s = 0.0;
  s.t_end_s = 0.00125;
  const FrameWindow w = frame_window(s, straight_run());
  EXPECT_EQ(w.count, 13);
  EXPECT_LE(w.time_s(w.count - 1), 0.00125);
}

TEST(FrameSchedule, AbsentWindowIsTheWholeTrajectory) {
  RenderSettings s;
  s.fps = 1000;  // 10 ms -> 10 periods -> 11 frames
  const FrameWindow w = frame_window(s, straight_run());
  EXPECT_DOUBLE_EQ(w.t_start_s, 0.0);
  EXPECT_DOUBLE_EQ(w.t_end_s, 0.01);
  EXPECT_EQ(w.count, 11);
}

TEST(FrameSchedule, WindowOutsideTheRecordingIsRefused) {
  RenderSettings s;
  s.t_end_s = 0.02;  // recording ends at 0.01 s
  EXPECT_EQ(key_of(s, straight_run()), "render.t_end");
  RenderSettings early;
  early.t_start_s = -0.001;
  EXPECT_EQ(key_of(early, straight_run()), "render.t_start");
}

TEST(FrameSchedule, AbsurdFrameCountIsRefused) {
  // 10 ms at 1e9 frames per second would be 1e7 files.
  RenderSettings s;
  s.fps = 1e9;
  EXPECT_EQ(key_of(s, straight_run()), "render.fps");
}

TEST(FrameSchedule, EmptyTrajectoryIsRefused) {
  EXPECT_THROW(frame_window(RenderSettings{}, Trajectory{}), std::invalid_argument);
}

TEST(SampleAt, InterpolatesLinearlyBetweenSamples) {
  Trajectory t;
  WheelSample a, b;
  a.time_s = 1.0;
  a.centre_m = {0.0, 0.01, 0.5};
  a.spin_angle_rad = 0.0;
  a.contacts.push_back(ContactSample{});
  b.time_s = 2.0;
  b.centre_m = {1.0, 0.03, 0.4};
  b.velocity_m_per_s = {2.0, 0.0, -1.0};
  b.spin_angle_rad = 2.0;
  t.samples = {a, b};
  // A quarter of the way: every interpolated quantity is a + (b - a) / 4.
  const WheelSample q = sample_at(t, 1.25);
  std::cout << "centre " << q.centre_m.transpose() << ", spin " << q.spin_angle_rad << "\n";
  EXPECT_NEAR(q.centre_m.x(), 0.25, 1e-15);
  EXPECT_NEAR(q.centre_m.y(), 0.015, 1e-15);
  EXPECT_NEAR(q.centre_m.z(), 0.475, 1e-15);
  EXPECT_NEAR(q.velocity_m_per_s.x(), 0.5, 1e-15);
  EXPECT_NEAR(q.velocity_m_per_s.z(), -0.25, 1e-15);
  EXPECT_NEAR(q.spin_angle_rad, 0.5, 1e-15);
  EXPECT_EQ(q.contacts.size(), 1u);                // nearer sample is a
  EXPECT_EQ(sample_at(t, 1.75).contacts.size(), 0u);  // nearer sample is b
  // Outside the recording: the end states.
  EXPECT_DOUBLE_EQ(sample_at(t, 0.0).centre_m.x(), 0.0);
  EXPECT_DOUBLE_EQ(sample_at(t, 3.0).centre_m.x(), 1.0);
}

}  // namespace
}  // namespace railjoint
