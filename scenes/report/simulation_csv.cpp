// The time series of a simulated crossing as CSV (simulation_csv.h).

#include "scenes/report/simulation_csv.h"

#include "sim/contact_phases.h"
#include "sim/crossing_model.h"
#include "sim/time_origin.h"

namespace railjoint {

void write_simulation_csv(const SimulationResult& r, std::ostream& out) {
  // A force run adds the track under the wheel (sim/force_outcome.h).
  const ForceOutcome* forces = r.inertial() && r.inertial()->forces ? &*r.inertial()->forces : nullptr;
  out << "t_s,x_m,z_m,zdot_m_per_s,contacts,contact_impulse_z_Ns,xdot_m_per_s,contact_force_z_N,z_kinematic_m,"
         "spin_rate_rad_per_s";
  // contact_y_m: where across the head the contact bearing the most touches
  // (empty in flight).
  if (forces) out << ",rail_z_m,sleeper_z_m,sprung_z_m,contact_y_m";
  // The lumped track's support forces (sim/track_support_forces.h).
  const TrackSupportOutcome* support = forces && forces->support ? &*forces->support : nullptr;
  if (support) out << ",rail_seat_N,ballast_N";
  // A bogie's wheels, each one's vertical contact force (wheel 0 leads).
  const std::size_t wheel_columns = forces ? forces->wheel_contact_force_N.size() : 0;
  for (std::size_t w = 0; w < wheel_columns; ++w) out << ",wheel" << w << "_contact_force_z_N";
  out << '\n';
  const std::vector<WheelSample>& samples = r.trajectory.samples;
  const double t0_s = simulation_time_origin_s(r);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const WheelSample& s = samples[k];
    double impulse_z = 0;
    for (const ContactSample& c : s.contacts) impulse_z += c.normal_impulse_Ns * c.normal.z();
    const double z_kinematic = r.model->reference_height_m(s.centre_m.x());
    out << s.time_s - t0_s << ',' << s.centre_m.x() << ',' << s.centre_m.z() << ',' << s.velocity_m_per_s.z() << ','
        << s.contacts.size() << ',' << impulse_z << ',' << s.velocity_m_per_s.x() << ','
        << vertical_contact_force_N(samples, k) << ',' << z_kinematic << ',' << s.spin_rate_rad_per_s;
    if (forces) {
      const TrackState& t = forces->track[k];
      out << ',' << t.rail_z_m << ',' << t.sleeper_z_m << ',' << t.sprung_z_m << ',';
      const ContactSample* bearing = nullptr;
      for (const ContactSample& c : s.contacts) {
        if (c.normal_impulse_Ns > 0.0 && (!bearing || c.normal_impulse_Ns > bearing->normal_impulse_Ns)) bearing = &c;
      }
      if (bearing) out << bearing->point_on_rail_m.y();
    }
    if (support) out << ',' << support->rail_seat_N[k] << ',' << support->ballast_N[k];
    for (std::size_t w = 0; w < wheel_columns; ++w) out << ',' << forces->wheel_contact_force_N[w][k];
    out << '\n';
  }
}

}  // namespace railjoint
