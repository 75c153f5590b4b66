#pragma once
// When frames are taken and what the wheel looks like at those instants.
// Frames sit at a fixed rate in SIMULATED time, independent of the physics
// step; the recorded trajectory is interpolated linearly between samples.
// Rendering reads recorded states and never drives a simulation.

#include "renders/render_settings.h"
#include "sim/trajectory.h"

namespace railjoint {

/// The frame times of a render: t_k = t_start + k / fps, k = 0 .. count - 1.
/// count = floor((t_end - t_start) fps + 1e-6) + 1, so both ends of the window
/// are frames when the window is a whole number of frame periods (the 1e-6 of
/// a period absorbs rounding, e.g. 0.001 s * 20000 = 19.999999999999996), and
/// otherwise the last frame is the last one before t_end.
struct FrameWindow {
  double t_start_s = 0.0;
  double t_end_s = 0.0;
  double fps = 1.0;
  long long count = 0;

  double time_s(long long k) const { return t_start_s + static_cast<double>(k) / fps; }
  double period_s() const { return 1.0 / fps; }
};

/// Resolves the window against the trajectory (absent ends = first / last
/// sample). Throws InputError ("render.t_start" / "render.t_end" /
/// "render.fps") when the window leaves the recorded time span or would write
/// more than kMaxFrameCount frames, std::invalid_argument for an empty trajectory.
FrameWindow frame_window(const RenderSettings& settings, const Trajectory& trajectory);

/// The wheel state at t_s: centre, velocity and spin interpolated linearly
/// between the two recorded samples around t_s (clamped to the ends); the
/// contacts, which cannot be interpolated, are those of the nearer sample.
WheelSample sample_at(const Trajectory& trajectory, double t_s);

}  // namespace railjoint
