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
// The taper of what rolling in hands the run, in decay lengths at each end.
constexpr double kTaper = 3.0;

// How much further back than its start a wheel rolls in at a joint, in
// decay lengths, the rest of the way over the joint's own track (roll_in):
// 3 leave the joint's part of the static line exp(-3) of what it was at
// the start (a free hinge at 79.9 m/s: P1 from 1.64 m 378.0406, 378.0422,
// 378.0418 and 378.0417 kN after 2, 3, 4 and 6, against 378.4963 kN
// rolled in on the continuous rail alone; docs/forces.md).
constexpr double kHingeRunUpDecayLengths = 3.0;

}  // namespace

double roll_in_duration_s(const JenkinsTrack& track, double wheel_mass_kg) {
  return kRollInEFolds * 2.0 * (track.track_mass_p2_kg + wheel_mass_kg) / track.track_damping_N_s_per_m;
}

namespace {

// The wheel's contact, the load on it and the static Hertz approach under it.
struct LevelContact {
  double hertz_constant = 0.0;
  double normal_z = 1.0;
  double load_N = 0.0;
  double sink_m = 0.0;
  double force_N(double rail_z_m, double wheel_z_m) const {
    return normal_z * hertz_force_N(hertz_constant, normal_z * (rail_z_m - wheel_z_m));
  }
};

// Rolls the wheel `bays` sleeper bays at v from its contact at x_from, by
// velocity Verlet steps of step_s cut at each bay's end. On a treadmill the
// track's motion and the wheel move back a bay at each bay's end (the wheel
// rolls from x_from again); otherwise the wheel rolls on along the track.
// Returns the contact's x at the end; `force_N` is the contact force there.
double roll_bays(DiscreteTrack& track, VerticalMass& mass, const LevelContact& contact, double x_from_m, double bays,
                 double s, bool treadmill, double v, double step_s, double& force_N, int& steps) {
  double x_m = x_from_m;  // the contact now
  double pressed_at_m = std::nan("");  // where it pressed in the last step (the run's read-out: discrete_track.h)
  // (contact at x) => (its force, the track pressed, the wheel's and the
  // track's accelerations, the second half kick).
  const auto accelerate = [&](double half_step_s) {
    force_N = contact.force_N(track.deflection_m(x_m, pressed_at_m), mass.z_m);
    track.press(x_m, force_N);
    pressed_at_m = x_m;
    mass.accelerate(force_N - contact.load_N, half_step_s);
    track.accelerate(half_step_s);
  };
  accelerate(0.0);
  for (double bay = 0; bay < bays; ++bay) {
    const double bay_end_s = s / v;
    const double bay_start_m = treadmill ? x_from_m : x_from_m + s * bay;
    double time_s = 0.0;
    while (time_s < bay_end_s - 1e-12) {
      const double h = std::min(step_s, bay_end_s - time_s);
      mass.advance(h);
      track.advance(h);
      time_s += h;
      x_m = bay_start_m + v * time_s;
      accelerate(0.5 * h);
      ++steps;
    }
    if (treadmill) {
      // The wheel back at x_from: the motion a bay back, the wheel with it,
      // the forces pressed again there (the wheel's kick is done; the
      // track's accelerations are recomputed from the same state).
      track.shift_motion(s);
      x_m = x_from_m;
      track.press(x_m, force_N);
      track.accelerate(0.0);
      pressed_at_m = x_m;
    } else {
      x_m = x_from_m + s * (bay + 1.0);
    }
  }
  return x_m;
}

// What the track's and the wheel's motion hold beyond the moving static
// state with the contact at x (the track left in that state), tapered to
// nothing over the track's last kTaper decay lengths each side: cut off
// square, the wheel's wake behind it (4e-6 m 6 decay lengths back, against
// 3e-5 m under the wheel at 50 m/s) would leave a step in the run's rail
// where the motion handed over ends.
RolledIn beyond_moving_static_state(DiscreteTrack& track, const VerticalMass& mass, const LevelContact& contact,
                                    double x_m, double v, double decay_length_m) {
  const DiscreteTrack::Motion rolled = track.motion();
  const DiscreteTrack::LineUnderLoad settled = track.static_line_under(contact.load_N, x_m);
  track.rest_under(contact.load_N, x_m, v);
  const DiscreteTrack::Motion at_rest = track.motion();
  const double x0_m = track.first_node_x_m();
  const double h_m = track.node_spacing_m();
  const double end_m = x0_m + h_m * static_cast<double>(rolled.w_m.size() - 1);
  const double taper_m = kTaper * decay_length_m;
  const auto window = [&](double x) {
    const double inside_m = std::min(x - x0_m, end_m - x);
    if (inside_m >= taper_m) return 1.0;
    return 0.5 - 0.5 * std::cos(std::numbers::pi * std::max(0.0, inside_m) / taper_m);
  };
  RolledIn out;
  out.track = rolled;
  for (std::size_t i = 0; i < rolled.w_m.size(); ++i) {
    const double c = window(x0_m + h_m * static_cast<double>(i));
    out.track.w_m[i] = c * (rolled.w_m[i] - at_rest.w_m[i]);
    out.track.v_m_per_s[i] = c * (rolled.v_m_per_s[i] - at_rest.v_m_per_s[i]);
  }
  for (std::size_t k = 0; k < rolled.psi_rad.size(); ++k) {  // a Timoshenko rail's segments, at their middles
    const double c = window(x0_m + h_m * (static_cast<double>(k) + 0.5));
    out.track.psi_rad[k] = c * (rolled.psi_rad[k] - at_rest.psi_rad[k]);
    out.track.psi_rate_rad_per_s[k] = c * (rolled.psi_rate_rad_per_s[k] - at_rest.psi_rate_rad_per_s[k]);
  }
  for (std::size_t j = 0; j < rolled.sleeper_z_m.size(); ++j) {
    const double c = window(track.sleeper_x_m(j));
    out.track.sleeper_z_m[j] = c * (rolled.sleeper_z_m[j] - at_rest.sleeper_z_m[j]);
    out.track.sleeper_v_m_per_s[j] = c * (rolled.sleeper_v_m_per_s[j] - at_rest.sleeper_v_m_per_s[j]);
  }
  out.track_x0_m = x0_m;
  out.wheel_z_m = mass.z_m - (settled.z_m - contact.sink_m);
  out.wheel_zdot_m_per_s = mass.zdot_m_per_s - v * settled.dz_dx;
  return out;
}

// The continuous rail's periodic state (roll_in without the joint).
RolledIn roll_in_on_continuous_rail(const DiscreteTrackSettings& settings, const RollingWheel& wheel,
                                    const LevelContact& contact, double v, double step_s, double duration_s) {
  const double s = settings.sleeper_spacing_m;
  DiscreteTrackSettings continuous = settings;
  continuous.joint_bending_stiffness_N_m_per_rad.reset();
  const double decay_length_m = 0.5 * DiscreteTrack::start_lead_m(continuous);  // 1 / beta_f
  DiscreteTrack track(continuous, s + kTreadmillClearance * decay_length_m);
  // The wheel's place among the sleepers, p in [0, s): it rolls from p - s
  // to p, a bay, and the track's motion moves back a bay, and again.
  const double p_m = wheel.contact_x_m - s * std::floor(wheel.contact_x_m / s);
  const double bays = std::max(1.0, std::ceil(v * duration_s / s));
  // The wheel's height above the path on which it would touch the unloaded
  // rail, and its rate, in the moving static state: sunk by Hertz's approach
  // below the rail's static line under it, and moving with that line.
  const DiscreteTrack::LineUnderLoad start = track.static_line_under(contact.load_N, p_m - s);
  track.rest_under(contact.load_N, p_m - s, v);
  VerticalMass mass(wheel.mass_kg, start.z_m - contact.sink_m, v * start.dz_dx);
  double force_N = 0.0;
  int steps = 0;
  const double x_m = roll_bays(track, mass, contact, p_m - s, bays, s, true, v, step_s, force_N, steps);
  RolledIn out = beyond_moving_static_state(track, mass, contact, x_m, v, decay_length_m);
  out.shift_m = x_m - wheel.contact_x_m;
  out.contact_force_N = force_N;
  out.steps = steps;
  return out;
}

}  // namespace

RolledIn roll_in(const DiscreteTrackSettings& settings, const RollingWheel& wheel, double hertz_constant,
                 double normal_z, double speed_m_per_s, double step_s, double duration_s) {
  const double v = speed_m_per_s;
  const double s = settings.sleeper_spacing_m;
  // Hertz along the normal: the vertical approach delta_z presses the
  // surfaces by n_z delta_z, and the vertical part of Hertz's force there
  // balances W at delta_z = G (W / n_z)^(2/3) / n_z.
  const double W = wheel.load_N;
  const LevelContact contact{hertz_constant, normal_z, W, hertz_approach_m(hertz_constant, W / normal_z) / normal_z};
  if (!settings.joint_bending_stiffness_N_m_per_rad) {
    return roll_in_on_continuous_rail(settings, wheel, contact, v, step_s, duration_s);
  }
  // At a joint the continuous rail's periodic state is not the track's: the
  // moving static state holds the joint's part of the line as if the track
  // answered at once, where its supports' dampers and its mass make it lag
  // (a free hinge 2.2 decay lengths ahead of a wheel at 79.9 m/s: 32.5 um of
  // the rail's sinking under the wheel in the static state, 23.8 um in the
  // track's own, docs/forces.md), and the difference rang on in the P2 mode
  // into the impact. So the wheel rolls in on the continuous rail
  // kHingeRunUpDecayLengths further back, where the joint's part is
  // exp(-kHingeRunUpDecayLengths) smaller, and on from there to its start
  // over the track with the joint.
  const double decay_length_m = 0.5 * DiscreteTrack::start_lead_m(settings);
  const double run_up_bays = std::ceil(kHingeRunUpDecayLengths * decay_length_m / s);
  const double x_from_m = wheel.contact_x_m - run_up_bays * s;
  RollingWheel back = wheel;
  back.contact_x_m = x_from_m;
  const RolledIn periodic = roll_in_on_continuous_rail(settings, back, contact, v, step_s, duration_s);
  DiscreteTrack track(settings, std::max(std::abs(x_from_m), std::abs(wheel.contact_x_m)) +
                                    kTreadmillClearance * decay_length_m);
  const DiscreteTrack::LineUnderLoad start = track.static_line_under(W, x_from_m);
  track.rest_under(W, x_from_m, v);
  track.add_motion(periodic.track, periodic.track_x0_m, periodic.shift_m);
  VerticalMass mass(wheel.mass_kg, start.z_m - contact.sink_m + periodic.wheel_z_m,
                    v * start.dz_dx + periodic.wheel_zdot_m_per_s);
  double force_N = 0.0;
  int steps = periodic.steps;
  const double x_m = roll_bays(track, mass, contact, x_from_m, run_up_bays, s, false, v, step_s, force_N, steps);
  RolledIn out = beyond_moving_static_state(track, mass, contact, x_m, v, decay_length_m);
  out.shift_m = x_m - wheel.contact_x_m;
  out.contact_force_N = force_N;
  out.steps = steps;
  return out;
}

}  // namespace railjoint
