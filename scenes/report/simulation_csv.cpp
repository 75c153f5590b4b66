// The time series of a simulated crossing as a table (simulation_csv.h).

#include "scenes/report/simulation_csv.h"

#include <cassert>
#include <limits>
#include <string>

#include "sim/contact_phases.h"
#include "sim/crossing_model.h"
#include "sim/time_origin.h"

namespace railjoint {

namespace {

// Where across the head the contact bearing the most touches; NaN in flight.
double bearing_contact_y_m(const WheelSample& s) {
  const ContactSample* bearing = nullptr;
  for (const ContactSample& c : s.contacts) {
    if (c.normal_impulse_Ns > 0.0 && (!bearing || c.normal_impulse_Ns > bearing->normal_impulse_Ns)) bearing = &c;
  }
  return bearing ? bearing->point_on_rail_m.y() : std::numeric_limits<double>::quiet_NaN();
}

double summed_impulse_z_Ns(const WheelSample& s) {
  double sum_Ns = 0;
  for (const ContactSample& c : s.contacts) sum_Ns += c.normal_impulse_Ns * c.normal.z();
  return sum_Ns;
}

// A history recorded beside the samples (one value per sample) as a new column.
void add_history(ColumnTable& table, std::string name, const std::vector<double>& history) {
  assert(history.size() >= table.rows());
  table.add_column(std::move(name), [&history](std::size_t k) { return history[k]; });
}

}  // namespace

ColumnTable simulation_table(const SimulationResult& r) {
  const std::vector<WheelSample>& s = r.trajectory.samples;
  const double t0_s = simulation_time_origin_s(r);
  ColumnTable table(s.size());
  table.add_column("t_s", [&](std::size_t k) { return s[k].time_s - t0_s; });
  table.add_column("x_m", [&](std::size_t k) { return s[k].centre_m.x(); });
  table.add_column("z_m", [&](std::size_t k) { return s[k].centre_m.z(); });
  table.add_column("zdot_m_per_s", [&](std::size_t k) { return s[k].velocity_m_per_s.z(); });
  table.add_column("contacts", [&](std::size_t k) { return static_cast<double>(s[k].contacts.size()); });
  table.add_column("contact_impulse_z_Ns", [&](std::size_t k) { return summed_impulse_z_Ns(s[k]); });
  table.add_column("xdot_m_per_s", [&](std::size_t k) { return s[k].velocity_m_per_s.x(); });
  table.add_column("contact_force_z_N", [&](std::size_t k) { return vertical_contact_force_N(s, k); });
  table.add_column("z_kinematic_m", [&](std::size_t k) { return r.model->reference_height_m(s[k].centre_m.x()); });
  table.add_column("spin_rate_rad_per_s", [&](std::size_t k) { return s[k].spin_rate_rad_per_s; });
  // A force run adds the track under the wheel (sim/force_outcome.h).
  const ForceOutcome* forces = r.inertial() && r.inertial()->forces ? &*r.inertial()->forces : nullptr;
  if (!forces) return table;
  const std::vector<TrackState>& track = forces->track;
  table.add_column("rail_z_m", [&](std::size_t k) { return track[k].rail_z_m; });
  table.add_column("sleeper_z_m", [&](std::size_t k) { return track[k].sleeper_z_m; });
  table.add_column("sprung_z_m", [&](std::size_t k) { return track[k].sprung_z_m; });
  table.add_column("contact_y_m", [&](std::size_t k) { return bearing_contact_y_m(s[k]); });
  // The lumped track's support forces (sim/track_support_forces.h).
  if (forces->support) {
    add_history(table, "rail_seat_N", forces->support->rail_seat_N);
    add_history(table, "ballast_N", forces->support->ballast_N);
  }
  // A bogie's wheels, each one's vertical contact force (wheel 0 leads).
  for (std::size_t w = 0; w < forces->wheel_contact_force_N.size(); ++w) {
    add_history(table, "wheel" + std::to_string(w) + "_contact_force_z_N", forces->wheel_contact_force_N[w]);
  }
  return table;
}

void write_simulation_csv(const SimulationResult& r, std::ostream& out) { write_csv(simulation_table(r), out); }

}  // namespace railjoint
