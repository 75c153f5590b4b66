#include "sim/contact_phases.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace railjoint {

double vertical_contact_force_N(const std::vector<WheelSample>& samples, std::size_t k) {
  // A sample's contacts acted over the step that ended at it (contact_span_s:
  // over the velocity's age where the solver weighed them so); the first
  // sample's (a force run's starting state) over the step that begins there.
  const std::size_t end = k == 0 ? 1 : k;
  if (end >= samples.size()) return 0.0;
  const double dt = contact_span_s(samples, end);
  if (!(dt > 0.0)) return 0.0;
  double impulse = 0.0;
  for (const ContactSample& c : samples[k].contacts) impulse += c.impulse_Ns().z();
  return impulse / dt;
}

ContactPhaseAnalysis analyse_contact_phases(const Trajectory& trajectory, const ReferenceHeight& reference,
                                            const PhaseDetection& detection) {
  const std::vector<WheelSample>& s = trajectory.samples;
  ContactPhaseAnalysis out;
  if (s.empty()) return out;

  // Contact per sample from the force the step carried. The first sample has
  // no step behind it: it takes the state of the second.
  std::vector<char> contact(s.size(), 0);
  out.vertical_force_N.assign(s.size(), 0.0);
  for (std::size_t k = 1; k < s.size(); ++k) {
    const double f = vertical_contact_force_N(s, k);
    out.vertical_force_N[k] = f;
    double normal_impulse = 0.0;
    for (const ContactSample& c : s[k].contacts) normal_impulse += c.normal_impulse_Ns;
    const double dt = s[k].time_s - s[k - 1].time_s;
    contact[k] = dt > 0.0 && normal_impulse / dt > detection.min_contact_force_N;
    if (f > out.peak_force_N) {
      out.peak_force_N = f;
      out.peak_force_time_s = s[k].time_s;
      out.peak_force_x_m = s[k].centre_m.x();
    }
  }
  contact[0] = s.size() > 1 ? contact[1] : 1;

  // Deviation from the reference path.
  for (const WheelSample& w : s) {
    const double d = w.centre_m.z() - reference(w.centre_m.x());
    if (std::abs(d) > out.max_deviation_m) {
      out.max_deviation_m = std::abs(d);
      out.max_deviation_x_m = w.centre_m.x();
    }
    out.max_rise_m = std::max(out.max_rise_m, d);
    out.max_sink_m = std::max(out.max_sink_m, -d);
  }

  // Flights: runs of contact-free samples that last long enough. Shorter
  // runs stay part of the contact phase around them.
  std::size_t k = 0;
  while (k < s.size()) {
    if (contact[k]) {
      ++k;
      continue;
    }
    std::size_t end = k;
    while (end + 1 < s.size() && !contact[end + 1]) ++end;
    const std::size_t before = k > 0 ? k - 1 : 0;
    const bool landed = end + 1 < s.size();
    const double stop_time = landed ? s[end + 1].time_s : s[end].time_s;
    const int samples = static_cast<int>(end - k + 1);
    double clearance = -std::numeric_limits<double>::infinity();
    for (std::size_t j = k; j <= end; ++j) clearance = std::max(clearance, s[j].centre_m.z() - reference(s[j].centre_m.x()));
    if (samples >= detection.min_flight_samples && stop_time - s[before].time_s >= detection.min_flight_s &&
        clearance >= detection.min_flight_clearance_m) {
      Flight f;
      f.first_sample = k;
      f.last_sample = end;
      f.liftoff_time_s = s[before].time_s;
      f.liftoff_x_m = s[before].centre_m.x();
      f.liftoff_z_m = s[before].centre_m.z();
      f.liftoff_zdot_m_per_s = s[k].velocity_m_per_s.z();
      f.landed = landed;
      if (landed) {
        f.landing_time_s = s[end + 1].time_s;
        f.landing_x_m = s[end + 1].centre_m.x();
      }
      f.duration_s = stop_time - f.liftoff_time_s;
      f.apex_time_s = f.liftoff_time_s;
      for (std::size_t j = k; j <= end; ++j) {
        const double rise = s[j].centre_m.z() - f.liftoff_z_m;
        if (rise > f.apex_height_m) {
          f.apex_height_m = rise;
          f.apex_time_s = s[j].time_s;
        }
        f.max_clearance_m = std::max(f.max_clearance_m, s[j].centre_m.z() - reference(s[j].centre_m.x()));
      }
      out.flights.push_back(f);
      if (!landed) out.ended_in_flight = true;
    }
    k = end + 1;
  }

  // Phases: contact between flights, flight during them.
  double t = s.front().time_s;
  double x = s.front().centre_m.x();
  for (const Flight& f : out.flights) {
    if (f.liftoff_time_s > t) out.phases.push_back({true, t, f.liftoff_time_s, x, f.liftoff_x_m});
    const double end_t = f.landed ? f.landing_time_s : s.back().time_s;
    const double end_x = f.landed ? f.landing_x_m : s.back().centre_m.x();
    out.phases.push_back({false, f.liftoff_time_s, end_t, f.liftoff_x_m, end_x});
    t = end_t;
    x = end_x;
  }
  if (s.back().time_s > t) out.phases.push_back({true, t, s.back().time_s, x, s.back().centre_m.x()});
  return out;
}

}  // namespace railjoint
