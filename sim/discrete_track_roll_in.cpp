#include "sim/discrete_track_roll_in.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/hertz_law.h"
#include "sim/vertical_mass.h"

namespace railjoint {

namespace {

// E-folds of the P2 mode's decay a wheel rolls in for (roll_in_duration_s):
// 4 of the 19 ms estimate, 3 of the 26 ms measured, leave 5e-2 of the
// start's ringing: a 0.05 m cosine dip's P1 and P2 at 50 m/s from starts
// 1.69, 3.33 and 8.25 m within 3e-5 and 5e-5 (2 e-folds: 1.7e-4 and
// 1.5e-4; at 80 m/s 4.9e-5 and 1.4e-4 against 7.1e-4 and 8.7e-4).
constexpr double kRollInEFolds = 4.0;

// The treadmill's reach each side of the wheel, in decay lengths 1 / beta_f.
constexpr double kTreadmillClearance = 8.0;
// The taper of what the treadmill hands the run, in decay lengths at each end.
constexpr double kTaper = 3.0;

}  // namespace

double roll_in_duration_s(const JenkinsTrack& track, double wheel_mass_kg) {
  return kRollInEFolds * 2.0 * (track.track_mass_p2_kg + wheel_mass_kg) / track.track_damping_N_s_per_m;
}

RolledIn roll_in(const DiscreteTrackSettings& settings, const RollingWheel& wheel, double hertz_constant,
                 double normal_z, double speed_m_per_s, double step_s, double duration_s) {
  const double v = speed_m_per_s;
  const double s = settings.sleeper_spacing_m;
  DiscreteTrackSettings continuous = settings;
  continuous.joint_bending_stiffness_N_m_per_rad.reset();
  const double decay_length_m = 0.5 * DiscreteTrack::start_lead_m(continuous);  // 1 / beta_f
  DiscreteTrack track(continuous, s + kTreadmillClearance * decay_length_m);
  // The wheel's place among the sleepers, p in [0, s): it rolls from p - s
  // to p, a bay, and the track's motion moves back a bay, and again.
  const double p_m = wheel.contact_x_m - s * std::floor(wheel.contact_x_m / s);
  const double bays = std::max(1.0, std::ceil(v * duration_s / s));
  // Hertz along the normal: the vertical approach delta_z presses the
  // surfaces by n_z delta_z, and the vertical part of Hertz's force there
  // balances W at delta_z = G (W / n_z)^(2/3) / n_z.
  const double W = wheel.load_N;
  const double sink_m = hertz_approach_m(hertz_constant, W / normal_z) / normal_z;
  const auto contact_N = [&](double rail_z_m, double wheel_z_m) {
    return normal_z * hertz_force_N(hertz_constant, normal_z * (rail_z_m - wheel_z_m));
  };
  // The wheel's height above the path on which it would touch the unloaded
  // rail, and its rate, in the moving static state: sunk by Hertz's approach
  // below the rail's static line under it, and moving with that line.
  const DiscreteTrack::LineUnderLoad start = track.static_line_under(W, p_m - s);
  track.rest_under(W, p_m - s, v);
  VerticalMass mass(wheel.mass_kg, start.z_m - sink_m, v * start.dz_dx);
  double force_N = 0.0;
  double x_m = p_m - s;  // the contact now
  // (contact at x) => (its force, the track pressed, the wheel's and the
  // track's accelerations, the second half kick).
  const auto accelerate = [&](double half_step_s) {
    force_N = contact_N(track.deflection_m(x_m), mass.z_m);
    track.press(x_m, force_N);
    mass.accelerate(force_N - W, half_step_s);
    track.accelerate(half_step_s);
  };
  RolledIn out;
  accelerate(0.0);
  for (double bay = 0; bay < bays; ++bay) {
    const double bay_end_s = s / v;
    double time_s = 0.0;
    while (time_s < bay_end_s - 1e-12) {
      const double h = std::min(step_s, bay_end_s - time_s);
      mass.advance(h);
      track.advance(h);
      time_s += h;
      x_m = p_m - s + v * time_s;
      accelerate(0.5 * h);
      ++out.steps;
    }
    // The wheel at p: the motion a bay back, the wheel with it, the forces
    // pressed again there (the wheel's kick is done; the track's
    // accelerations are recomputed from the same state).
    track.shift_motion(s);
    x_m = p_m - s;
    track.press(x_m, force_N);
    track.accelerate(0.0);
  }
  // The motion beyond the moving static state where the wheel now stands.
  const DiscreteTrack::Motion rolled = track.motion();
  const DiscreteTrack::LineUnderLoad settled = track.static_line_under(W, x_m);
  track.rest_under(W, x_m, v);
  const DiscreteTrack::Motion at_rest = track.motion();
  // Tapered to nothing over the treadmill's last kTaper decay lengths each
  // side: cut off square, the wheel's wake behind it (4e-6 m 6 decay
  // lengths back, against 3e-5 m under the wheel at 50 m/s) would leave a
  // step in the run's rail where the motion handed over ends.
  const double x0_m = track.first_node_x_m();
  const double h_m = track.node_spacing_m();
  const double end_m = x0_m + h_m * static_cast<double>(rolled.w_m.size() - 1);
  const double taper_m = kTaper * decay_length_m;
  const auto window = [&](double x) {
    const double inside_m = std::min(x - x0_m, end_m - x);
    if (inside_m >= taper_m) return 1.0;
    return 0.5 - 0.5 * std::cos(std::numbers::pi * std::max(0.0, inside_m) / taper_m);
  };
  out.track = rolled;
  for (std::size_t i = 0; i < rolled.w_m.size(); ++i) {
    const double c = window(x0_m + h_m * static_cast<double>(i));
    out.track.w_m[i] = c * (rolled.w_m[i] - at_rest.w_m[i]);
    out.track.v_m_per_s[i] = c * (rolled.v_m_per_s[i] - at_rest.v_m_per_s[i]);
  }
  for (std::size_t j = 0; j < rolled.sleeper_z_m.size(); ++j) {
    const double c = window(track.sleeper_x_m(j));
    out.track.sleeper_z_m[j] = c * (rolled.sleeper_z_m[j] - at_rest.sleeper_z_m[j]);
    out.track.sleeper_v_m_per_s[j] = c * (rolled.sleeper_v_m_per_s[j] - at_rest.sleeper_v_m_per_s[j]);
  }
  out.track_x0_m = x0_m;
  out.shift_m = x_m - wheel.contact_x_m;
  out.wheel_z_m = mass.z_m - (settled.z_m - sink_m);
  out.wheel_zdot_m_per_s = mass.zdot_m_per_s - v * settled.dz_dx;
  out.contact_force_N = force_N;
  return out;
}

}  // namespace railjoint
