#include "sim/track_support_forces.h"

#include <algorithm>

namespace railjoint {

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
