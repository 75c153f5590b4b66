#include "sim/track_support_forces.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/force_peaks.h"

namespace railjoint {

namespace {

// A support recorded at every sample.
bool whole(const SupportHistory& h, std::size_t samples) {
  return h.rail_seat_N.size() == samples && h.ballast_N.size() == samples && samples > 0;
}

}  // namespace

std::optional<TrackSupportOutcome> discrete_track_support_outcome(const std::vector<double>& time_s,
                                                                  const std::vector<SupportHistory>& supports) {
  TrackSupportOutcome o;
  std::size_t seat = 0, ballast = 0;
  o.rail_seat_peak_N = o.ballast_peak_N = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < supports.size(); ++k) {
    const SupportHistory& h = supports[k];
    if (!whole(h, time_s.size())) continue;
    const auto top_seat = std::max_element(h.rail_seat_N.begin(), h.rail_seat_N.end());
    const auto top_ballast = std::max_element(h.ballast_N.begin(), h.ballast_N.end());
    if (*top_seat > o.rail_seat_peak_N) {
      o.rail_seat_peak_N = *top_seat;
      o.rail_seat_peak_time_s = time_s[static_cast<std::size_t>(top_seat - h.rail_seat_N.begin())];
      seat = k;
    }
    if (*top_ballast > o.ballast_peak_N) {
      o.ballast_peak_N = *top_ballast;
      o.ballast_peak_time_s = time_s[static_cast<std::size_t>(top_ballast - h.ballast_N.begin())];
      ballast = k;
    }
  }
  if (!std::isfinite(o.rail_seat_peak_N)) return std::nullopt;
  o.rail_seat_peak_x_m = supports[seat].x_m;
  o.ballast_peak_x_m = supports[ballast].x_m;
  o.rail_seat_static_N = supports[seat].rail_seat_static_N;
  o.ballast_static_N = supports[ballast].ballast_static_N;
  o.rail_seat_N = supports[seat].rail_seat_N;
  o.ballast_N = supports[seat].ballast_N;
  return o;
}

std::optional<RailSeatP2> discrete_rail_seat_p2(const std::vector<double>& time_s,
                                                const std::vector<SupportHistory>& supports, double from_s,
                                                double to_s, double cutoff_Hz) {
  const SupportHistory* struck = nullptr;
  double largest_N = -std::numeric_limits<double>::infinity();
  for (const SupportHistory& h : supports) {
    if (!whole(h, time_s.size())) continue;
    for (std::size_t k = 0; k < time_s.size() && time_s[k] <= to_s; ++k) {
      if (time_s[k] >= from_s && h.rail_seat_N[k] > largest_N) {
        largest_N = h.rail_seat_N[k];
        struck = &h;
      }
    }
  }
  if (!struck) return std::nullopt;
  const LowPassedTop top = lowpassed_top(time_s, struck->rail_seat_N, cutoff_Hz, from_s, to_s);
  return RailSeatP2{top.force_N, top.time_s, struck->x_m, from_s, to_s};
}

TrackSupportForces lumped_track_support_forces(const std::vector<double>& time_s, const std::vector<TrackState>& track,
                                               const LumpedTrackSettings& settings, double gravity_m_per_s2) {
  const TrackSupportSettings& support = settings.support;
  const double rail_weight_N = settings.rail_mass_kg * gravity_m_per_s2;
  const double track_weight_N = (settings.rail_mass_kg + support.sleeper_mass_kg) * gravity_m_per_s2;
  TrackSupportForces f;
  const std::size_t n = std::min(time_s.size(), track.size());
  f.rail_seat_N.resize(n);
  f.ballast_N.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const TrackState& now = track[k];
    double rail_rate_m_per_s = 0.0, sleeper_rate_m_per_s = 0.0;
    if (k > 0 && time_s[k] > time_s[k - 1]) {
      const double dt = time_s[k] - time_s[k - 1];
      rail_rate_m_per_s = (now.rail_z_m - track[k - 1].rail_z_m) / dt;
      sleeper_rate_m_per_s = (now.sleeper_z_m - track[k - 1].sleeper_z_m) / dt;
    }
    // Compression of the pad: the rail below the sleeper; of the ballast: the sleeper below its rest.
    f.rail_seat_N[k] =
        pad_force_N(support, now.rail_z_m, rail_rate_m_per_s, now.sleeper_z_m, sleeper_rate_m_per_s, rail_weight_N);
    f.ballast_N[k] = ballast_force_N(support, now.sleeper_z_m, sleeper_rate_m_per_s, track_weight_N);
  }
  return f;
}

}  // namespace railjoint
