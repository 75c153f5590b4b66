#include "sim/momentum_jump.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace railjoint {

namespace {

// Whether the solver applied a contact impulse in the step that ended at
// sample k.
bool contact_solved(const WheelSample& sample) {
  return std::any_of(sample.contacts.begin(), sample.contacts.end(),
                     [](const ContactSample& c) { return c.normal_impulse_Ns > 0.0; });
}

// The vertical acceleration over the step that ended at sample k, over the
// time its velocity change covers (step_span_s): a held step cut short
// before a landing's first touch is no part of the landing.
double step_acceleration(const std::vector<WheelSample>& s, std::size_t k) {
  return (s[k].velocity_m_per_s.z() - s[k - 1].velocity_m_per_s.z()) / step_span_s(s, k);
}

// A step whose contact the solver took after at least this many samples
// without a solved contact is a landing when it changes the momentum by
// min_landing_jump_Ns, whatever its acceleration: a landing after a low flight can
// be slower than a pivot's v^2 / R (a 5.2 N s landing at 38.6 m/s after a
// flight of 3.4 mm and 0.15 um is 2x v^2 / R in its one fine step, and was
// missed). A pivot's contact that flickers open is unsolved one step at a
// time.
constexpr int kLandingAfterFreeSamples = 3;

// Whether the step that ended at sample k is the first with a solved
// contact after at least `free_samples` samples without one.
bool landing_after_flight(const std::vector<WheelSample>& s, std::size_t k, int free_samples) {
  const std::size_t n = static_cast<std::size_t>(std::max(free_samples, 0));
  if (n == 0 || k <= n || !contact_solved(s[k])) return false;
  for (std::size_t j = k - n; j < k; ++j) {
    if (contact_solved(s[j])) return false;
  }
  return true;
}

// The samples a side of a jump is fitted on: up to `count` samples walking
// from `from` towards `to` (inclusive, either direction). On a side where
// the wheel is on the rail (rolling, pivoting about a corner) only the steps
// whose contact the solver took count: a step in which a pivot's contact
// opened by the arc's rise over the step, (v dt)^2 / 2R, and went unsolved
// is a numerical fall under the load, not the motion along the arc (every
// other step on a fast pivot at 1e-6 s). A side with no solved step is a
// flight and keeps every step.
std::vector<std::size_t> fit_samples(const std::vector<WheelSample>& s, std::size_t from, std::size_t to,
                                     std::size_t count) {
  const auto towards = [&](std::size_t k) { return from <= to ? k + 1 : k - 1; };
  const auto done = [&](std::size_t k) { return from <= to ? k > to : k < to || k == static_cast<std::size_t>(-1); };
  bool on_rail = false;
  std::size_t seen = 0;
  for (std::size_t k = from; !done(k) && seen < count; k = towards(k), ++seen) on_rail = on_rail || contact_solved(s[k]);
  std::vector<std::size_t> picked;
  for (std::size_t k = from; !done(k) && picked.size() < count; k = towards(k)) {
    if (k >= 1 && (!on_rail || contact_solved(s[k]))) picked.push_back(k);
  }
  return picked;
}

// Least-squares line of one velocity component through the picked samples,
// evaluated at t, each velocity at the instant it belongs to
// (WheelSample::velocity_time_s: on a rail the start of its step, in flight
// carried on from there). Labelling it at the step's midpoint instead cost
// half a step of the pivot's or the flight's acceleration:
// 0.5 * 143 m/s^2 * 1e-6 s = 7e-5 m/s, 2e-4 of a 300 N s scenario-2 jump.
// Times are taken relative to t to keep the normal equations well conditioned.
struct FittedLine {
  double value = 0.0;  ///< at the evaluation time
  double slope = 0.0;  ///< per second
};

FittedLine fitted_velocity(const std::vector<WheelSample>& s, const std::vector<std::size_t>& picked, double t,
                           int axis) {
  double n = 0, st = 0, sz = 0, stt = 0, stz = 0;
  for (const std::size_t k : picked) {
    const double dt = s[k].velocity_time_s - t;
    const double z = s[k].velocity_m_per_s[axis];
    n += 1;
    st += dt;
    sz += z;
    stt += dt * dt;
    stz += dt * z;
  }
  assert(n > 0);
  const double det = n * stt - st * st;
  if (n < 2 || std::abs(det) < 1e-300) return {sz / n, 0.0};
  // v = a + b dt; at dt = 0 the value is a.
  return {(sz * stt - st * stz) / det, (n * stz - st * sz) / det};
}

double wheel_x_at(const std::vector<WheelSample>& s, double t) {
  auto it = std::lower_bound(s.begin(), s.end(), t, [](const WheelSample& w, double time) { return w.time_s < time; });
  if (it == s.begin()) return s.front().centre_m.x();
  if (it == s.end()) return s.back().centre_m.x();
  const WheelSample& b = *it;
  const WheelSample& a = *(it - 1);
  const double f = (t - a.time_s) / (b.time_s - a.time_s);
  return a.centre_m.x() + f * (b.centre_m.x() - a.centre_m.x());
}

}  // namespace

JumpDetection jump_detection_for(double mass_kg, double speed_m_per_s, double radius_m, double vertical_force_N,
                                 double touch_distance_m) {
  JumpDetection detection;
  detection.mass_kg = mass_kg;
  detection.vertical_force_N = vertical_force_N;
  const double smooth = speed_m_per_s * speed_m_per_s / radius_m + std::abs(vertical_force_N) / mass_kg;
  // 5x: the exact narrow phase leaves resting contacts no velocity noise to
  // mistake for an impact (Bullet's own had it, and needed 20x), and a
  // shallow landing located in one step may be only 16x (a 5.4 N s landing
  // at 11.6 m/s was missed at 20x).
  detection.impact_acceleration_m_per_s2 = 5.0 * smooth;
  detection.smooth_acceleration_m_per_s2 = 3.0 * smooth;
  // Coarse steps: the smooth bound is a sum of two alternatives (a pivot
  // needs the load to supply v^2 / R, so the larger of the two is the real
  // bound), so half again above it is out of reach of smooth motion. The
  // smallest jumps of the validation set are 0.03 v (scenario 1, 50 m/s); a
  // third of that in one step is no noise. Scenario 1 at 50 m/s is thus
  // caught up to 1.8e-4 s steps, scenario 2 up to 3.5e-4 s; beyond, a step
  // cannot tell an impact from a pivot (the stability study's coarse cases).
  detection.coarse_jump_m_per_s = 0.01 * speed_m_per_s;
  detection.coarse_acceleration_m_per_s2 = 1.5 * smooth;
  detection.min_jump_Ns = 1e-4 * mass_kg * speed_m_per_s;
  // A landing after a flight needs no noise floor of the fast steps' kind
  // (landing_after_flight): at 1e-4 M v (3.5 N s at 46 m/s) landings of 1.2
  // and 2.6 N s on 60E1 went missing. Below 1e-6 M v a landing is under the
  // accuracy the strike is vouched for (1e-4 of at least 1e-2 M v), and the
  // self-check finds any landing that the step cannot resolve
  // (SelfCheckLimits::landing_step_bias).
  detection.min_landing_jump_Ns = 1e-6 * mass_kg * speed_m_per_s;
  detection.touch_distance_m = touch_distance_m;
  return detection;
}

std::vector<MomentumJump> find_momentum_jumps(const Trajectory& trajectory, const JumpDetection& detection) {
  const std::vector<WheelSample>& s = trajectory.samples;
  std::vector<MomentumJump> jumps;
  if (s.size() < 3) return jumps;

  // 1. Impact steps: acceleration far above anything smooth motion produces.
  //    Grow each core run of such steps by the neighbouring steps that are
  //    still above the smooth bound (the overlap builds up over a few steps).
  std::vector<std::pair<std::size_t, std::size_t>> events;
  std::vector<bool> landing_only;  // per event: its cores are landings after a flight, none a fast step
  for (std::size_t k = 1; k < s.size(); ++k) {
    const double acceleration = std::abs(step_acceleration(s, k));
    const double velocity_change = std::abs(s[k].velocity_m_per_s.z() - s[k - 1].velocity_m_per_s.z());
    const bool fine_impact =
        acceleration > detection.impact_acceleration_m_per_s2 && detection.mass_kg * velocity_change >= detection.min_jump_Ns;
    const bool coarse_impact =
        acceleration > detection.coarse_acceleration_m_per_s2 && velocity_change >= detection.coarse_jump_m_per_s;
    const bool landing = landing_after_flight(s, k, kLandingAfterFreeSamples) &&
                         detection.mass_kg * velocity_change >= detection.min_landing_jump_Ns;
    if (!fine_impact && !coarse_impact && !landing) continue;
    std::size_t first = k;
    std::size_t last = k;
    while (first > 1 && std::abs(step_acceleration(s, first - 1)) > detection.smooth_acceleration_m_per_s2) --first;
    while (last + 1 < s.size() && std::abs(step_acceleration(s, last + 1)) > detection.smooth_acceleration_m_per_s2) {
      ++last;
    }
    // The merge window joins the parts of one fast impact; a landing after a
    // flight is an impact of its own however soon it comes (a 20 us flight
    // after a strike on 60E1 was folded into the strike, 1e-3 of it).
    const bool fast = fine_impact || coarse_impact;
    if (!events.empty() && (first <= events.back().second + static_cast<std::size_t>(detection.skip_samples) ||
                            (fast && s[first - 1].time_s - s[events.back().second].time_s < detection.merge_window_s))) {
      events.back().second = std::max(events.back().second, last);
      landing_only.back() = landing_only.back() && !fast;
    } else {
      events.emplace_back(first, last);
      landing_only.push_back(!fast);
    }
    k = last;
  }

  const std::size_t fit = static_cast<std::size_t>(std::max(detection.fit_samples, 2));
  const std::size_t skip = static_cast<std::size_t>(std::max(detection.skip_samples, 0));
  for (std::size_t e = 0; e < events.size(); ++e) {
    const auto [first, last] = events[e];
    MomentumJump jump;
    jump.first_sample = first;
    jump.last_sample = last;

    // 2. Impact instant: the extrapolated sides are compared there, and
    //    after a scenario-2 strike zdot falls at v^2/R (5000 m/s^2 at
    //    50 m/s): 1 us of error is 0.25 % of the jump.
    jump.time_s = s[first - 1].time_s;
    {
      const ContactSample* struck = nullptr;
      for (const ContactSample& c : s[first].contacts) {
        if (struck == nullptr || c.normal_impulse_Ns * c.normal.z() > struck->normal_impulse_Ns * struck->normal.z()) {
          struck = &c;
        }
      }
      if (struck != nullptr) {
        const double closing_m_per_s = -s[first - 1].velocity_m_per_s.dot(struck->normal);
        const double overlap_m = detection.touch_distance_m - struck->distance_m;
        if (closing_m_per_s > 0 && overlap_m > 0) {
          const double earliest = first >= 2 ? s[first - 2].time_s : s[first - 1].time_s;
          jump.time_s = std::max(earliest, jump.time_s - overlap_m / closing_m_per_s);
        }
      }
    }
    jump.wheel_x_m = wheel_x_at(s, jump.time_s);

    // 3. Both sides fitted with a line and extrapolated to the instant: after
    //    a scenario-2 impact the wheel pivots or flies, zdot is no plateau.
    const std::size_t previous_end = e > 0 ? events[e - 1].second : 0;
    const std::size_t next_start = e + 1 < events.size() ? events[e + 1].first - 1 : s.size() - 1;
    const std::size_t pre_last = first - 1 >= previous_end + skip ? first - 1 - skip : first - 1;
    const std::size_t post_first = std::min(last + skip, next_start);
    const std::vector<std::size_t> before = fit_samples(s, pre_last, previous_end, fit);
    const std::vector<std::size_t> after = fit_samples(s, post_first, next_start, fit);
    if (before.empty() || after.empty()) continue;
    const FittedLine zdot_before = fitted_velocity(s, before, jump.time_s, 2);
    const FittedLine zdot_after = fitted_velocity(s, after, jump.time_s, 2);
    jump.zdot_before_m_per_s = zdot_before.value;
    jump.zdot_after_m_per_s = zdot_after.value;
    jump.xdot_before_m_per_s = fitted_velocity(s, before, jump.time_s, 0).value;
    jump.xdot_after_m_per_s = fitted_velocity(s, after, jump.time_s, 0).value;
    jump.jump_Ns = detection.mass_kg * (jump.zdot_after_m_per_s - jump.zdot_before_m_per_s);
    // A contact that flickers open for one step lets the load pull the wheel
    // down and the next step stops it again: large accelerations, no net jump.
    if (!(std::abs(jump.jump_Ns) >= (landing_only[e] ? detection.min_landing_jump_Ns : detection.min_jump_Ns))) continue;

    // 4. Cross-check from the solver's contact impulses. Over the impact
    //    steps the contacts also carry the steady load, which the external
    //    force over the same time takes out again.
    double contact_z = 0;
    double largest = -1;
    for (std::size_t k = first; k <= last; ++k) {
      for (const ContactSample& c : s[k].contacts) {
        const double jz = c.normal_impulse_Ns * c.normal.z();
        // Friction impulses are exactly zero for frictionless contact.
        contact_z += jz + c.friction_impulse_Ns.z();
        jump.horizontal_impulse_Ns += c.normal_impulse_Ns * c.normal.x() + c.friction_impulse_Ns.x();
        if (jz > largest) {
          largest = jz;
          jump.struck_rail = c.rail_index;
          jump.struck_point_m = c.point_on_rail_m;
        }
      }
    }
    // That is M (zdot[last] - zdot[first - 1]), exactly, by Bullet's own
    // momentum balance; those two velocities belong to instants either side
    // of the impact (velocity_time_s), so each side's fitted acceleration
    // takes its smooth motion out to the impact instant: on a pivot into a
    // landing one step of v^2 / R (0.8 % of a 325 N s jump at 39 m/s).
    jump.from_contacts_Ns = contact_z + detection.vertical_force_N * (s[last].time_s - s[first - 1].time_s) -
                            detection.mass_kg * (zdot_before.slope * (jump.time_s - s[first - 1].velocity_time_s) +
                                                 zdot_after.slope * (s[last].velocity_time_s - jump.time_s));

    Eigen::Vector3d left = Eigen::Vector3d::Zero();
    int left_count = 0;
    for (const ContactSample& c : s[first - 1].contacts) {
      if (c.rail_index != jump.struck_rail && c.distance_m <= 0) {
        left += c.point_on_rail_m;
        ++left_count;
      }
    }
    if (left_count > 0) jump.left_point_m = left / left_count;
    jumps.push_back(jump);
  }
  return jumps;
}

double find_liftoff_time_s(const Trajectory& trajectory, std::size_t after_sample, int sustained_samples) {
  const std::vector<WheelSample>& s = trajectory.samples;
  int run = 0;
  for (std::size_t k = after_sample + 1; k < s.size(); ++k) {
    const bool closed = std::any_of(s[k].contacts.begin(), s[k].contacts.end(),
                                    [](const ContactSample& c) { return c.distance_m <= 0; });
    run = closed ? 0 : run + 1;
    if (run >= sustained_samples) return s[k + 1 - static_cast<std::size_t>(run)].time_s;
  }
  return -1.0;
}

}  // namespace railjoint
