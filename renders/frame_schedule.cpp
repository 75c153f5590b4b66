#include "renders/frame_schedule.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "support/input_error.h"

namespace railjoint {

namespace {
std::string seconds(double t) {
  std::ostringstream out;
  out.precision(9);
  out << t << " s";
  return out.str();
}
}  // namespace

FrameWindow frame_window(const RenderSettings& settings, const Trajectory& trajectory) {
  check_render_settings(settings);
  if (trajectory.samples.empty()) throw std::invalid_argument("cannot render an empty trajectory (no samples)");
  const double first = trajectory.samples.front().time_s;
  const double last = trajectory.samples.back().time_s;
  // Recorded times are sums of steps; a frame window typed as 0.02 must not be
  // rejected because the last sample landed at 0.019999999999.
  const double slack = 1e-9 * std::max(1.0, std::abs(last - first));
  std::ostringstream span_text;  // (a stream, not "[" + string: GCC 12 warns falsely on that)
  span_text << "[" << seconds(first) << ", " << seconds(last) << "]";
  const std::string span = span_text.str();

  FrameWindow window;
  window.fps = settings.fps;
  window.t_start_s = settings.t_start_s.value_or(first);
  window.t_end_s = settings.t_end_s.value_or(last);
  if (window.t_start_s < first - slack || window.t_start_s > last + slack) {
    throw InputError("render.t_start", "render.t_start = " + seconds(window.t_start_s) +
                                               " lies outside the recorded trajectory " + span);
  }
  if (window.t_end_s < first - slack || window.t_end_s > last + slack) {
    throw InputError("render.t_end", "render.t_end = " + seconds(window.t_end_s) +
                                             " lies outside the recorded trajectory " + span);
  }
  if (window.t_end_s < window.t_start_s) {
    throw InputError("render.t_end", "render.t_end = " + seconds(window.t_end_s) +
                                             " is before render.t_start = " + seconds(window.t_start_s));
  }
  const double periods = (window.t_end_s - window.t_start_s) * settings.fps;
  if (periods + 1.0 > static_cast<double>(kMaxFrameCount)) {
    std::ostringstream message;
    message << "render.fps = " << settings.fps << " over a window of " << seconds(window.t_end_s - window.t_start_s)
            << " would write " << std::floor(periods) + 1 << " frames, more than the limit of " << kMaxFrameCount
            << "; lower render.fps or narrow render.t_start / render.t_end";
    throw InputError("render.fps", message.str());
  }
  window.count = static_cast<long long>(std::floor(periods + 1e-6)) + 1;
  return window;
}

WheelSample sample_at(const Trajectory& trajectory, double t_s) {
  const auto& samples = trajectory.samples;
  if (samples.empty()) throw std::invalid_argument("cannot sample an empty trajectory");
  if (t_s <= samples.front().time_s) return samples.front();
  if (t_s >= samples.back().time_s) return samples.back();
  // First sample strictly after t_s; the one before it is at or before t_s.
  const auto after = std::upper_bound(samples.begin(), samples.end(), t_s,
                                      [](double t, const WheelSample& s) { return t < s.time_s; });
  const WheelSample& b = *after;
  const WheelSample& a = *(after - 1);
  const double span = b.time_s - a.time_s;
  const double w = span > 0.0 ? (t_s - a.time_s) / span : 0.0;

  WheelSample out;
  out.time_s = t_s;
  out.centre_m = (1.0 - w) * a.centre_m + w * b.centre_m;
  out.velocity_m_per_s = (1.0 - w) * a.velocity_m_per_s + w * b.velocity_m_per_s;
  out.spin_angle_rad = (1.0 - w) * a.spin_angle_rad + w * b.spin_angle_rad;
  out.contacts = w < 0.5 ? a.contacts : b.contacts;
  return out;
}

}  // namespace railjoint
