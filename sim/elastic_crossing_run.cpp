#include "sim/elastic_crossing_run.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>
#include <optional>
#include <variant>

#include "models/kinematic_trajectory.h"
#include "sim/force_contact_geometry.h"
#include "sim/force_run_track.h"
#include "sim/discrete_track_roll_in.h"
#include "sim/force_run_vehicle.h"
#include "sim/hertz_law.h"
#include "sim/implicit_contact_damper.h"
#include "sim/pulse_window.h"
#include "sim/rail_end_patch_share.h"
#include "support/run_interrupt.h"
#include "sim/vertical_mass.h"

namespace railjoint {

namespace {

// What a rail's contact remembers from one step to the next. Hunt-Crossley
// needs the rate at which the contact was made (a contact the run starts in
// was made at rest: pure Hertz); on a bending beam the rail surface under a
// contact that slides along it moves by its slope too. The gap and its rate
// at the last step locate a contact's onset within the step.
struct RailContactMemory {
  bool touching = false;
  double impact_rate_m_per_s = 0.0;
  bool had_contact = false;
  double previous_contact_x_m = 0.0;
  double previous_distance_m = 0.0;
  double previous_separating_rate_m_per_s = 0.0;
  double pressed_N = 0.0;  // the vertical force it pressed in the last step (the implicit damper's)
  bool elliptical_law = false;   // Hertz's law at the last step (force_contact_geometry.h)
  bool near_law_switch = false;  // bearing, and that law may switch within the next steps
  // At the last step (its defaults where it did not bear), for the spanning
  // contact's work (contact_stage).
  struct Spanning {
    double share = 1.0;                     // its merged-patch share
    double unshared_hertz_energy_J = 0.0;   // Hertz's energy at its effective penetration, unshared
    double elastic_N = 0.0;                 // its elastic force
    double pressed_by_other_m = 0.0;        // the approach the other rail end's load pressed
  } spanning;
};

// A wheel at one step: its centre moves along x at the carrier's speed, its
// vertical motion is a VerticalMass (vertical_mass.h).
struct WheelState {
  Eigen::Vector3d centre_m;
  double zdot_m_per_s;
};

// What the contact stage hands the rest of the step.
struct ContactForces {
  std::vector<ContactSample> contacts;
  double wheel_force_z_N = 0.0;
  double hertz_energy_J = 0.0;
  double carrier_power_W = 0.0;    // the carrier's work rate on the contacts
  double contact_damping_W = 0.0;  // Hunt and Crossley's part beyond Hertz's
  double spanning_work_J = 0.0;    // the spanning contact's work no energy books, over the step
};

// The energy balance (CrossingRun::energy_surplus_J): the energy at the
// start, and what the carrier put in and the dampers took out since, each
// power integrated by the trapezoidal rule over the step (the scheme's
// order: the surplus falls as dt^2), and the spanning contact's work
// (contact_stage: a force no potential's gradient, whose work no stored
// energy books).
struct EnergyLedger {
  bool started = false;
  double start_energy_J = 0.0;
  double carrier_work_J = 0.0;
  double spanning_work_J = 0.0;
  double dissipated_J = 0.0;
  double previous_carrier_power_W = 0.0;
  double previous_damping_W = 0.0;
};

// What a run reads and does not change: the model and the constants of its loop.
struct ForceRun {
  const CrossingModel& model;
  double damping_factor;  // makes an isolated impact rebound at e (hertz_law.h)
  double M;
  double v;
  double dt;
  const ForceContactGeometry& rails;  // the touching point, normal and Hertz's constant
  std::vector<double> behind_m;       // each wheel's distance behind the leading one (0 for it)
};

// The run's wheels: one, or a bogie's two (the leading one first, the one
// the trajectory records), each with its contacts' memory.
struct Wheels {
  std::vector<VerticalMass> mass;
  std::vector<std::array<RailContactMemory, 2>> memory;
  std::vector<double> load_N;  // the vehicle's load on each, at the step's end
};

// (wheel k's vertical state, time) => (its centre and vertical rate): the
// carrier holds x = x0 - behind + v t.
WheelState wheel_state(const ForceRun& r, const VerticalMass& wheel, std::size_t k, double time_s) {
  const Eigen::Vector3d& c0 = r.model.start.centre_m;
  return {Eigen::Vector3d(c0.x() - r.behind_m[k] + r.v * time_s, c0.y(), wheel.z_m), wheel.zdot_m_per_s};
}

// The discrete track's supports whose forces a run records: three each side
// of the joint (the impact's and its neighbours').
constexpr std::size_t kRecordedSupports = 6;

// (model, wheels behind the leading one) => (the track in its start state,
// each wheel's start, the discrete track's Jenkins reading). Built in place: the discrete track's factorisation
// does not move. One wheel starts as the model placed it. A bogie's wheels
// start in the static state under both (build_crossing_model's
// start_rail_under_wheels): each on the kinematic path at its x, sunk by
// Hertz's approach there and by the rail's deflection under both loads at
// its contact, with that deflection's rate as the loads move on.
void make_track(const CrossingModel& model, const std::vector<double>& behind_m, ForceRunTrack& track, Wheels& wheels,
                std::optional<JenkinsTrack>& jenkins_track, std::optional<double>& start_force_N) {
  const InertialSettings& inertial = *model.settings.inertial();
  const ElasticCrossingSettings& elastic = *inertial.elastic();
  const double M = model.simulated_wheel.mass_kg;
  const double v = model.simulated_wheel.speed_m_per_s;
  wheels.mass.assign(1, VerticalMass(M, model.start.centre_m.z(), model.start.vertical_velocity_m_per_s));
  if (elastic.discrete_track) {
    // At rest under the wheels' static loads.
    const double W = inertial.wheel_load_N + M * kStandardGravity_m_per_s2;
    DiscreteTrack& beam = track.emplace<DiscreteTrack>(*elastic.discrete_track, model.discrete_track_half_length_m);
    std::vector<DiscreteTrack::PointLoad> loads;
    for (double behind : behind_m) loads.push_back({W, model.start_contact_x_m - behind});
    if (behind_m.size() > 1) {
      const std::vector<CrossingModel::RailUnderWheel>& line = model.start_rail_under_wheels;
      assert(line.size() == behind_m.size());
      wheels.mass.clear();
      for (std::size_t k = 0; k < behind_m.size(); ++k) {
        const double x_m = model.start.centre_m.x() - behind_m[k];
        const double z_m = kinematic_centre_height_m(model.joint, model.simulated_wheel, x_m) -
                           model.start_hertz_sink_m + line[k].z_m;
        const double zdot_m_per_s =
            v * (kinematic_centre_slope(model.joint, model.simulated_wheel, x_m, +1) + line[k].dz_dx);
        wheels.mass.emplace_back(M, z_m, zdot_m_per_s);
      }
    }
    // The recorded supports' static forces with the (leading) wheel
    // standing on the joint, a bogie's trailing one axle_spacing behind (the
    // force analysis's reference), and the track as Jenkins's formulas read
    // it, from this track's own factorisation; then the start.
    beam.record_supports_near(0.0, kRecordedSupports);
    std::vector<DiscreteTrack::PointLoad> on_joint;
    for (double behind : behind_m) on_joint.push_back({W, 0.0 - behind});
    beam.rest_under(on_joint);
    beam.note_static_support_forces();
    jenkins_track = beam.jenkins_equivalent();
    beam.rest_under(loads, v);
    // Then the motion each wheel rolling over the sleepers adds to that
    // state (discrete_track_roll_in.h): the run starts in its periodic state.
    const double roll_in_s = roll_in_duration_s(*jenkins_track, M);
    // The rail's height and rate under each wheel's contact, as it moves on.
    const auto rail_at = [&](double x_m) {
      return std::array<double, 2>{beam.deflection_m(x_m),
                                   beam.deflection_rate_m_per_s(x_m) + v * beam.deflection_slope(x_m)};
    };
    for (std::size_t k = 0; k < loads.size(); ++k) {
      const RolledIn rolled = roll_in(*elastic.discrete_track, {loads[k].x_m, M, W}, model.hertz_constant_m_per_N2_3,
                                      model.start_normal_z, v, inertial.force_time_step_s, roll_in_s);
      std::vector<std::array<double, 2>> before;
      for (const DiscreteTrack::PointLoad& l : loads) before.push_back(rail_at(l.x_m));
      beam.add_motion(rolled.track, rolled.track_x0_m, rolled.shift_m);
      // Wheel k moves as it did rolling in; every other wheel with the rail
      // this motion moves under it, so that its contact keeps the pressure
      // of its own rolled-in state.
      for (std::size_t j = 0; j < loads.size(); ++j) {
        const std::array<double, 2> after = rail_at(loads[j].x_m);
        const double dz_m = j == k ? rolled.wheel_z_m : after[0] - before[j][0];
        const double dzdot_m_per_s = j == k ? rolled.wheel_zdot_m_per_s : after[1] - before[j][1];
        wheels.mass[j].z_m += dz_m;
        wheels.mass[j].zdot_m_per_s += dzdot_m_per_s;
        wheels.mass[j].half_step_zdot_m_per_s = wheels.mass[j].zdot_m_per_s;
      }
      if (k == 0) start_force_N = rolled.contact_force_N;
    }
  }
  if (elastic.track) track.emplace<LumpedTrack>(*elastic.track, model.start_track);
  wheels.memory.assign(wheels.mass.size(), {});
  wheels.load_N.assign(wheels.mass.size(), 0.0);
}

// (model, wheels at the start) => (the load on them: constant, a sprung mass or a bogie).
ForceRunVehicle make_vehicle(const CrossingModel& model, const Wheels& wheels) {
  const InertialSettings& inertial = *model.settings.inertial();
  const ElasticCrossingSettings& elastic = *inertial.elastic();
  ForceRunVehicle vehicle(ConstantLoad{inertial.wheel_load_N});
  if (elastic.vehicle) {
    const double mass_kg = elastic.vehicle->sprung_mass_kg.value_or(inertial.wheel_load_N / kStandardGravity_m_per_s2);
    // The suspension unstrained at the wheel's start and moving with it (on
    // the discrete track rolled in: discrete_track_roll_in.h), as a bogie's.
    vehicle.emplace<SprungMass>(*elastic.vehicle, inertial.wheel_load_N, mass_kg, wheels.mass.front().z_m,
                                wheels.mass.front().zdot_m_per_s);
  }
  if (elastic.bogie) {
    vehicle.emplace<Bogie>(*elastic.bogie, inertial.wheel_load_N, bogie_body_mass_kg(*elastic.bogie, inertial.wheel_load_N, kStandardGravity_m_per_s2),
                           wheels.mass);
  }
  return vehicle;
}

// One rail end's contact at the step's end, before the two are merged.
struct BearingRailEnd {
  CylinderContact contact;
  HertzAtContact hertz;
  double rail_z_m = 0.0;
  double drag_rate_m_per_s = 0.0;  // the contact's speed times the slope the carrier drags it along
  double separating_rate_m_per_s = 0.0;
  double penetration_m = 0.0;  // 0 where it does not bear
};

// Its patch along the track at a penetration: Hertz's force there and its
// semi-length (force_contact_geometry.h).
RailEndPatch patch_of(const ForceRun& r, const BearingRailEnd& b, double penetration_m) {
  const double x_m = b.contact.point_on_rail_m.x();
  if (!(penetration_m > 0.0)) return {x_m, 0.0, 0.0};
  return {x_m, patch_semi_length_m(b.hertz, penetration_m, r.model.simulated_wheel.radius_m),
          hertz_force_N(b.hertz.hertz_constant_m_per_N2_3, penetration_m)};
}

// (run, track, the wheel's bearing rail ends, their memory, their elastic
// forces, Hertz's approaches, step) => each one's Hunt and Crossley force and
// the rate at which its approach closes at the step's end. Undamped (or no
// damped contact bearing): the plain law at the predicted rate, as before.
// Damped: the damper taken implicitly over the step
// (implicit_contact_damper.h), with the rate each newton pressed adds
// under both contacts: the wheel's half kick 1/M, the track's
// (kick_mobility_per_kg) and a Timoshenko rail's local give c(x_k, x_j)
// read one step late (DiscreteTrack::local_shear_m_per_N), both contacts'
// (each read the other's give without its rate before: a damped balance
// closed only to 2e-4..1e-3 where both rail ends bore, docs/forces.md).
template <class Track>
DampedContactForces forces_of(const ForceRun& r, const Track& track, const std::array<BearingRailEnd, 2>& bearing,
                              const std::array<RailContactMemory, 2>& memory, const std::array<double, 2>& elastic_N,
                              const std::array<double, 2>& penetration_m, double step_s) {
  DampedContactForces out;
  std::array<DampedContact, 2> contacts;
  std::array<bool, 2> bears{};
  bool damped = false;
  for (std::size_t k = 0; k < 2; ++k) {
    bears[k] = bearing[k].contact.found && penetration_m[k] > 0.0;
    const double impact_rate_m_per_s = memory[k].impact_rate_m_per_s;
    damped = damped || (bears[k] && r.damping_factor > 0.0 && impact_rate_m_per_s > 0.0);
    contacts[k] = {elastic_N[k], impact_rate_m_per_s > 0.0 ? r.damping_factor / impact_rate_m_per_s : 0.0,
                   -bearing[k].separating_rate_m_per_s, bearing[k].contact.normal.z(), memory[k].pressed_N};
  }
  if (!damped) {
    for (std::size_t k = 0; k < 2; ++k) {
      out.force_N[k] = elastic_N[k];
      out.closing_m_per_s[k] = contacts[k].closing_m_per_s;
    }
    return out;
  }
  std::array<std::array<double, 2>, 2> slowing{};
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t j = 0; j < 2; ++j) {
      if (!bears[k] || !bears[j]) continue;
      const double x_k = bearing[k].contact.point_on_rail_m.x(), x_j = bearing[j].contact.point_on_rail_m.x();
      slowing[k][j] = 0.5 * step_s * (1.0 / r.M + track.kick_mobility_per_kg(x_k, x_j));
      if constexpr (kTrackBends<Track>) slowing[k][j] += track.local_shear_m_per_N(x_k, x_j) / step_s;
    }
  }
  return solve_damped_contacts(contacts, bears, slowing);
}

// (wheel position and velocity, track displacement, memory) => (contacts,
// their forces on the wheel, the track pressed, memory, max penetration).
// Hertz (Hunt-Crossley) on each rail's nearest point, with Hertz's constant
// there (force_contact_geometry.h), the rail moved by the
// track's displacement. On a bending track the displacement is read at the
// contact: found once with the deflection under the centre, then again with
// the one at that contact (the beam's slope, ~1e-3, moves the point by far
// less than its own size). A contact made within the step is located there
// by the gap's zero between the last step's and this one's (linear: the
// rate then, which Hunt-Crossley's damping scales with, is off by O(dt^2)).
// The wheel's and the rail's rates are the ones predicted at the step's end.
template <class Track>
ContactForces contact_stage(const ForceRun& r, const WheelState& wheel, Track& track, double time_s, double step_s,
                            double sample_step_s, std::array<RailContactMemory, 2>& memory,
                            double& max_penetration_m) {
  const Eigen::Vector3d& p = wheel.centre_m;
  const Eigen::Vector3d wheel_velocity(r.v, 0, wheel.zdot_m_per_s);
  const double breaking_m = r.model.settings.contact_breaking_threshold_m;
  WheelCylinder cylinder = r.rails.wheel_at(p);
  ContactForces out;
  std::array<BearingRailEnd, 2> bearing;
  for (std::size_t k = 0; k < memory.size(); ++k) {
    RailContactMemory& m = memory[k];
    const int rail = static_cast<int>(k);
    // Where this contact pressed its force in the last step (a Timoshenko
    // rail reads that force under the contact: DiscreteTrack::deflection_m).
    const double pressed_at_x_m = m.had_contact ? m.previous_contact_x_m : std::nan("");
    const auto rail_z_at = [&](double x_m) {
      if constexpr (kTrackBends<Track>) return track.deflection_m(x_m, pressed_at_x_m);
      return track.deflection_m(x_m);
    };
    cylinder.centre_m = Eigen::Vector3d(p.x(), p.y(), p.z() - track.deflection_m(p.x()));
    ForceContact found = r.rails.find(rail, cylinder, breaking_m);
    if constexpr (kTrackBends<Track>) {
      if (found.contact.found) {
        cylinder.centre_m.z() = p.z() - rail_z_at(found.contact.point_on_rail_m.x());
        found = r.rails.find(rail, cylinder, breaking_m);
      }
    }
    const CylinderContact& contact = found.contact;
    const double contact_x_m = contact.point_on_rail_m.x();
    const double rail_z = rail_z_at(contact_x_m);
    // d/dt w(x_c(t)) = dw/dt + x_c' dw/dx: the contact slides at the wheel's
    // speed on a face, stays put on a corner it pivots about.
    // The carrier drags it along the read-out's slope, a Timoshenko rail's
    // local shear's included (DiscreteTrack::drag_slope: its own force
    // pressed where it was a step ago).
    // Its own force's read-out c(x, x) F moves with it; the rate of that
    // force's part is taken with the force (forces_of).
    double slope_rate_m_per_s = 0.0, drag_rate_m_per_s = 0.0;
    DiscreteTrack::OwnShear own;
    if constexpr (kTrackBends<Track>) {
      const double contact_speed_m_per_s =
          contact.found && m.had_contact ? (contact_x_m - m.previous_contact_x_m) / step_s : r.v;
      own = track.own_shear(contact_x_m, pressed_at_x_m);
      slope_rate_m_per_s =
          contact_speed_m_per_s * (track.deflection_slope(contact_x_m) - own.slope_per_N * own.force_N);
      drag_rate_m_per_s = contact_speed_m_per_s * track.drag_slope(contact_x_m, pressed_at_x_m);
    }
    const double rail_zdot = track.deflection_rate_m_per_s(contact_x_m) + slope_rate_m_per_s;
    const bool had_contact = m.had_contact;
    m.had_contact = contact.found;
    m.previous_contact_x_m = contact_x_m;
    const bool penetrating = contact.found && contact.distance_m < 0.0;
    if (!contact.found) {
      m.touching = false;
      m.near_law_switch = false;
      m.spanning = {};
      continue;
    }
    const double separating_rate = wheel_velocity.dot(contact.normal) - rail_zdot * contact.normal.z();
    if (penetrating && !m.touching) {
      // The onset: the fraction of the step at which the gap closed, and the
      // rate interpolated there (a contact the run starts in: made at rest).
      double onset_rate = separating_rate;
      if (had_contact && m.previous_distance_m > 0.0) {
        const double fraction = m.previous_distance_m / (m.previous_distance_m - contact.distance_m);
        onset_rate = m.previous_separating_rate_m_per_s + fraction * (separating_rate - m.previous_separating_rate_m_per_s);
      }
      m.impact_rate_m_per_s = time_s > 0.0 ? std::max(0.0, -onset_rate) : 0.0;
    }
    m.touching = penetrating;
    m.elliptical_law = found.hertz.ellipse.has_value();
    m.near_law_switch = penetrating && r.rails.near_law_switch(rail, found, 2.0 * r.v * r.dt);
    m.previous_distance_m = contact.distance_m;
    m.previous_separating_rate_m_per_s = separating_rate;
    const double penetration_m = -contact.distance_m;
    max_penetration_m = std::max(max_penetration_m, penetration_m);
    BearingRailEnd& b = bearing[k];
    b.contact = contact;
    b.hertz = found.hertz;
    b.rail_z_m = rail_z;
    b.drag_rate_m_per_s = drag_rate_m_per_s;
    b.separating_rate_m_per_s = separating_rate;
    b.penetration_m = penetrating ? penetration_m : 0.0;
  }
  // The wheel spanning the joint: the two rail ends press on each other and
  // merge where their patches overlap (rail_end_patch_share.h).
  const SpanningContact spanning = spanning_contact(
      {bearing[0].penetration_m, bearing[1].penetration_m},
      [&](int i, double penetration_m) { return patch_of(r, bearing[static_cast<std::size_t>(i)], penetration_m); },
      r.rails.spanning_coupling_modulus_Pa());
  const std::array<double, 2>& share = spanning.share;
  // Each one's penetration less the other rail end's load's approach there
  // (the same where one bears alone), Hertz's force (its share) at it, and
  // Hunt and Crossley's.
  std::array<double, 2> penetration_m{}, elastic_N{};
  for (std::size_t k = 0; k < bearing.size(); ++k) {
    const BearingRailEnd& b = bearing[k];
    if (!b.contact.found) continue;
    penetration_m[k] = b.penetration_m > 0.0 ? std::max(0.0, spanning.effective_penetration_m[k]) : 0.0;
    elastic_N[k] = share[k] * hertz_force_N(b.hertz.hertz_constant_m_per_N2_3, penetration_m[k]);
  }
  const DampedContactForces forces = forces_of(r, track, bearing, memory, elastic_N, penetration_m, step_s);
  for (std::size_t k = 0; k < bearing.size(); ++k) {
    const BearingRailEnd& b = bearing[k];
    if (!b.contact.found) {
      memory[k].pressed_N = 0.0;
      continue;
    }
    const CylinderContact& contact = b.contact;
    const double G = b.hertz.hertz_constant_m_per_N2_3;
    const double pressed_by_other_m = b.penetration_m - penetration_m[k];
    const double force_N = forces.force_N[k];
    const double contact_x_m = contact.point_on_rail_m.x();
    out.wheel_force_z_N += force_N * contact.normal.z();
    track.press(contact_x_m, force_N * contact.normal.z());
    memory[k].pressed_N = force_N * contact.normal.z();
    // The carrier cancels the contact's push along x, working at -F n_x v,
    // and drags the contact along the bent rail, F n_z x_c' dw/dx (the
    // normal is taken untilted by the rail's ~1e-3 slope); Hunt and
    // Crossley's part beyond Hertz's takes F_damping d(delta)/dt. A shared
    // patch stores its share of Hertz's energy, and two patches pressing on
    // each other the coupling's, F_0 c F_1: half of it with each.
    const double unshared_energy_J = hertz_energy_J(G, penetration_m[k]);
    out.hertz_energy_J += share[k] * unshared_energy_J + 0.5 * elastic_N[k] * pressed_by_other_m;
    // The spanning contact's force (rail_end_patch_share.h) is no
    // potential's gradient: its share s and the approach p the other rail
    // end's load presses move with both penetrations and both touching
    // points. The energy booked, U = s E_H(e) + F p / 2 (F = s H(e), e =
    // delta - p), changes by dU = F d(delta) + E_H ds + (p dF - F dp) / 2:
    // the force's work and a rest that loading and unloading do not give
    // back. That rest is booked as work put in, each factor at the step's
    // mean (the exact product rule of the increments), so the balance keeps
    // the stepping's error, s dE_H - F de. Without it the balance kept up
    // to 6.5e-3 of its scale on random scenes at every step from 4e-6 to
    // 1.25e-7 s (docs/forces.md, "Where the balance's tail came from").
    const RailContactMemory::Spanning now{share[k], unshared_energy_J, elastic_N[k], pressed_by_other_m};
    const RailContactMemory::Spanning& was = memory[k].spanning;
    out.spanning_work_J +=
        0.5 * (was.unshared_hertz_energy_J + now.unshared_hertz_energy_J) * (now.share - was.share) +
        0.25 * ((was.pressed_by_other_m + now.pressed_by_other_m) * (now.elastic_N - was.elastic_N) -
                (was.elastic_N + now.elastic_N) * (now.pressed_by_other_m - was.pressed_by_other_m));
    memory[k].spanning = now;
    out.carrier_power_W += force_N * (contact.normal.z() * b.drag_rate_m_per_s - contact.normal.x() * r.v);
    if (penetration_m[k] > 0.0) out.contact_damping_W += (force_N - elastic_N[k]) * forces.closing_m_per_s[k];
    ContactSample c;
    c.point_on_rail_m = contact.point_on_rail_m + Eigen::Vector3d(0, 0, b.rail_z_m);
    c.normal = contact.normal;
    c.distance_m = contact.distance_m;
    c.normal_impulse_Ns = force_N * sample_step_s;  // over the sample's step
    c.rail_index = static_cast<int>(k);
    c.normal_velocity_m_per_s = b.separating_rate_m_per_s;
    out.contacts.push_back(c);
  }
  return out;
}

// (wheels, vehicle, track, contact forces at the step's end) => (the energy
// there, the carrier's and the dampers' work over the step by the trapezoidal
// rule) for the balance: kinetic (vertical; the held x speed's is constant),
// the loads' potentials, the springs', Hertz's.
template <class Track, class Vehicle>
void energy_stage(const ForceRun& r, const Wheels& wheels, const Track& track, const Vehicle& vehicle,
                  const std::vector<ContactForces>& forces, double step_s, EnergyLedger& ledger, CrossingRun& run) {
  double energy_J = 0.0;
  double damping_W = 0.0;
  double carrier_power_W = 0.0;
  double spanning_work_J = 0.0;
  for (std::size_t k = 0; k < wheels.mass.size(); ++k) {
    const double z = wheels.mass[k].z_m;
    const double zdot = wheels.mass[k].zdot_m_per_s;
    energy_J += 0.5 * r.M * zdot * zdot + r.M * kStandardGravity_m_per_s2 * z + forces[k].hertz_energy_J;
    damping_W += forces[k].contact_damping_W;
    carrier_power_W += forces[k].carrier_power_W;
    spanning_work_J += forces[k].spanning_work_J;
  }
  energy_J += vehicle.energy_J(wheels.mass);
  damping_W += vehicle.dissipation_W(wheels.mass);
  energy_J += track.energy_J();
  damping_W += track.dissipation_W();
  if (ledger.started) {
    ledger.carrier_work_J += 0.5 * (ledger.previous_carrier_power_W + carrier_power_W) * step_s;
    ledger.dissipated_J += 0.5 * (ledger.previous_damping_W + damping_W) * step_s;
    ledger.spanning_work_J += spanning_work_J;
  } else {
    ledger.start_energy_J = energy_J;
  }
  ledger.started = true;
  ledger.previous_carrier_power_W = carrier_power_W;
  ledger.previous_damping_W = damping_W;
  run.energy_surplus_J = std::max(run.energy_surplus_J, energy_J - ledger.start_energy_J - ledger.carrier_work_J -
                                                           ledger.spanning_work_J + ledger.dissipated_J);
}

// (contact forces, wheels, vehicle) => (every body's acceleration at the
// step's end, the step's second half kick of `half_step_s`; 0 at the start).
template <class Track, class Vehicle>
void accelerate_stage(const ForceRun& r, const std::vector<ContactForces>& forces, Wheels& wheels, Track& track,
                      Vehicle& vehicle, double half_step_s) {
  vehicle.loads_N(wheels.mass, wheels.load_N);
  for (std::size_t k = 0; k < wheels.mass.size(); ++k) {
    wheels.mass[k].accelerate(forces[k].wheel_force_z_N - r.M * kStandardGravity_m_per_s2 - wheels.load_N[k],
                              half_step_s);
  }
  track.accelerate(half_step_s);
  vehicle.accelerate(wheels.load_N, half_step_s);
}

// (leading wheel, track, vehicle, every wheel's contact force) => (a sample
// and its track state in the run; with more than one wheel, each wheel's
// vertical contact force).
template <class Track, class Vehicle>
void record_stage(const ForceRun& r, const WheelState& wheel, const Track& track, const Vehicle& vehicle,
                  double time_s, std::vector<ContactForces>& forces, CrossingRun& run) {
  WheelSample s;
  s.time_s = time_s;
  const Eigen::Vector3d& p = wheel.centre_m;
  const Eigen::Vector3d& c0 = r.model.start.centre_m;
  const double radius_m = r.model.simulated_wheel.radius_m;
  s.centre_m = p;
  s.velocity_m_per_s = Eigen::Vector3d(r.v, 0.0, wheel.zdot_m_per_s);
  s.velocity_time_s = time_s;  // Verlet's velocity is the step end's
  s.spin_angle_rad = (p.x() - c0.x()) / radius_m;
  s.spin_rate_rad_per_s = r.v / radius_m;
  s.contacts = std::move(forces.front().contacts);
  run.trajectory.samples.push_back(std::move(s));
  TrackState state = track.state_under(p.x());
  state.sprung_z_m = vehicle.sprung_z_m();
  run.track_states.push_back(state);
  if (forces.size() > 1) {
    run.wheel_contact_force_N.resize(forces.size());
    for (std::size_t k = 0; k < forces.size(); ++k) run.wheel_contact_force_N[k].push_back(forces[k].wheel_force_z_N);
  }
}

// (every wheel, track) => (each wheel's contacts and forces, the track
// pressed): the contact stage once per wheel, each at its own x with its
// own memory. The track takes every wheel's press before it accelerates,
// so the order of the wheels does not matter.
template <class Track>
void contacts_stage(const ForceRun& r, Wheels& wheels, Track& track, double time_s, double step_s, double sample_step_s,
                    std::vector<ContactForces>& forces, double& max_penetration_m) {
  forces.resize(wheels.mass.size());
  for (std::size_t k = 0; k < wheels.mass.size(); ++k) {
    forces[k] = contact_stage(r, wheel_state(r, wheels.mass[k], k, time_s), track, time_s, step_s, sample_step_s,
                              wheels.memory[k], max_penetration_m);
  }
}

// Whether a contact of any wheel, not yet made, closes within the next two
// steps at its rate: the step that makes it is to be taken fine.
bool contact_closing(const Wheels& wheels, double step_s) {
  for (const std::array<RailContactMemory, 2>& memory : wheels.memory) {
    for (const RailContactMemory& m : memory) {
      if (m.had_contact && !m.touching && m.previous_distance_m + 2.0 * step_s * m.previous_separating_rate_m_per_s <= 0.0)
        return true;
    }
  }
  return false;
}

// Where a bearing contact's Hertz law switches (a face's elliptical
// constant to a cut edge's empirical one and back, 12 % apart on 60E1 under
// a 1:40 cone), the force at a given penetration jumps. A step across the
// switch would take the mean of the two laws' forces over the whole step
// (velocity Verlet's trapezoid), an impulse error of the step times the jump:
// P1 then converged at first order (548007.8, 548034.2, 548047.0 N at 1e-6,
// 0.5e-6, 0.25e-6 s). The switch sits at a wheel-centre x (the contact point
// depends on x alone), so it is located before the step, as the rigid runs
// locate impacts: bisected to kLawSwitchBracket_s, the step ends just before
// it and a step that short crosses it, each law's force then stepped on its
// own side. Only a contact near a switch (force_contact_geometry.h,
// near_law_switch) is looked ahead, one contact search a step.
constexpr double kLawSwitchBracket_s = 1e-13;

struct LawSwitch {
  double before_s;  // the law still the last step's
  double after_s;   // the new one
};

// (wheels at time from_s) => the first switch of a bearing contact's Hertz
// law in (from_s, to_s], if any.
std::optional<LawSwitch> law_switch_within(const ForceRun& r, const Wheels& wheels, double from_s, double to_s) {
  if (!r.rails.law_can_switch()) return std::nullopt;
  std::optional<LawSwitch> first;
  WheelCylinder cylinder = r.rails.wheel_at(Eigen::Vector3d::Zero());
  for (std::size_t k = 0; k < wheels.mass.size(); ++k) {
    for (std::size_t rail = 0; rail < 2; ++rail) {
      const RailContactMemory& m = wheels.memory[k][rail];
      if (!m.near_law_switch) continue;
      const auto same_law_at = [&](double time_s) {
        cylinder.centre_m = wheel_state(r, wheels.mass[k], k, time_s).centre_m;
        const std::optional<bool> elliptical = r.rails.elliptical_law_at(static_cast<int>(rail), cylinder);
        return elliptical && *elliptical == m.elliptical_law;
      };
      if (same_law_at(to_s)) continue;
      double before_s = from_s, after_s = to_s;
      while (after_s - before_s > kLawSwitchBracket_s) {
        const double mid_s = 0.5 * (before_s + after_s);
        if (mid_s <= before_s || mid_s >= after_s) break;
        (same_law_at(mid_s) ? before_s : after_s) = mid_s;
      }
      if (!first || after_s < first->after_s) first = LawSwitch{before_s, after_s};
    }
  }
  return first;
}

// Half a period of the wheel on the Hertz spring at the static load
// (stiffness 1.5 P0 / delta0, delta0 = G P0^(2/3)): how long a contact made
// keeps the pulse window open before the force rises (pulse_window.h).
double hertz_half_period_s(const ForceRun& r, double static_N) {
  const double approach_m = hertz_approach_m(r.model.hertz_constant_m_per_N2_3, static_N);
  return std::numbers::pi * std::sqrt(r.M * approach_m / (1.5 * static_N));
}

// The step over the impact's pulse: sim.refined_time_step on a track that
// rings (pulse_window.h), the run's own step on a rigid one, shortened by
// sqrt(1 + alpha) for a damped contact. Hunt and Crossley's force is
// (1 + alpha d(delta)/dt / v0) times Hertz's, up to (1 + alpha) times at
// the onset, so the contact closes on a spring that much stiffer: its
// frequency w is sqrt(1 + alpha) times higher, and Verlet's (w dt)^2 error
// with it. Measured on the lumped default scene, P1 at 1e-6 s throughout:
// -4.55e-6 undamped, -1.0e-5 at e = 0.5 (alpha 1.43), -2.4e-5 at e = 0.2
// (alpha 4.92): 2.2x and 5.3x, against 1 + alpha = 2.4 and 5.9; the error
// was made between the onset and P1 (those steps alone at 1/16 of it: within
// 2e-7). Undamped (alpha 0) the steps are as they were.
double damped_pulse_step_s(const ForceRun& r, bool track_rings) {
  const double undamped_s = track_rings ? r.model.settings.refined_time_step_s : r.dt;
  return undamped_s / std::sqrt(1.0 + r.damping_factor);
}

// The stepping loop, written once and compiled for each track and vehicle:
// velocity Verlet for every body (vertical_mass.h), one evaluation of the
// forces a step. A sample every sim.force_time_step; over the impact's pulse
// (pulse_window.h) its step is split into steps of at most
// sim.refined_time_step on an elastic track, a damped contact's sqrt(1 +
// alpha) finer there and on the rigid track (damped_pulse_step_s). Each sample holds the leading wheel's state at its
// time and its contacts there, with the impulse F dt of the sample's step.
template <class Track, class Vehicle>
void step_loop(const ForceRun& r, Wheels& wheels, Track& track, Vehicle& vehicle, CrossingRun& run) {
  const SimSettings& settings = r.model.settings;
  double time_s = 0.0;
  double max_penetration_m = 0.0;
  EnergyLedger ledger;
  std::vector<ContactForces> forces;
  std::vector<double> force_N;
  const auto wheel_forces = [&]() -> const std::vector<double>& {
    force_N.clear();
    for (const ContactForces& f : forces) force_N.push_back(f.wheel_force_z_N);
    return force_N;
  };
  const int fine_splits =
      std::max(1, static_cast<int>(std::ceil(r.dt / damped_pulse_step_s(r, kTrackRings<Track>) - 1e-9)));
  // The start: its contact forces (the static load on the rail) and accelerations.
  const double first_step_s = std::min(r.dt, r.model.end_time_s);
  contacts_stage(r, wheels, track, 0.0, first_step_s, first_step_s, forces, max_penetration_m);
  accelerate_stage(r, forces, wheels, track, vehicle, 0.0);
  energy_stage(r, wheels, track, vehicle, forces, 0.0, ledger, run);
  PulseWindow window(wheel_forces(), hertz_half_period_s(r, std::max(forces.front().wheel_force_z_N, 1.0)));
  track.record_supports();
  record_stage(r, wheel_state(r, wheels.mass.front(), 0, 0.0), track, vehicle, 0.0, forces, run);
  while (time_s < r.model.end_time_s - 1e-12) {
    const double step_s = std::min(r.dt, r.model.end_time_s - time_s);
    const bool fine = window.fine_after(wheel_forces(), contact_closing(wheels, step_s), time_s);
    const int splits = fine ? fine_splits : 1;
    const double start_s = time_s;
    const auto step_to = [&](double end_s) {
      const double h = end_s - time_s;
      // (every body) => (positions at the step's end, rates predicted there).
      for (VerticalMass& wheel : wheels.mass) wheel.advance(h);
      track.advance(h);
      vehicle.advance(h);
      time_s = end_s;
      contacts_stage(r, wheels, track, time_s, h, step_s, forces, max_penetration_m);
      accelerate_stage(r, forces, wheels, track, vehicle, 0.5 * h);
      energy_stage(r, wheels, track, vehicle, forces, h, ledger, run);
      ++run.steps;
      poll_run_interrupt(run.steps);
      if (h <= settings.refined_time_step_s * (1 + 1e-9)) ++run.refined_steps;
    };
    for (int i = 1; i <= splits; ++i) {
      const double end_s = i == splits ? start_s + step_s : start_s + step_s * i / splits;
      // A Hertz law switching within the step: up to it, across it, on.
      for (int events = 0; events < 4; ++events) {
        const std::optional<LawSwitch> law_switch = law_switch_within(r, wheels, time_s, end_s);
        if (!law_switch) break;
        if (law_switch->before_s > time_s) step_to(law_switch->before_s);
        if (!(law_switch->after_s < end_s)) break;
        step_to(law_switch->after_s);
      }
      step_to(end_s);
    }
    track.record_supports();
    record_stage(r, wheel_state(r, wheels.mass.front(), 0, time_s), track, vehicle, time_s, forces, run);
  }
  run.max_penetration_m = max_penetration_m;
}

}  // namespace

CrossingRun run_elastic_crossing(const CrossingModel& model) {
  const InertialSettings& inertial = *model.settings.inertial();
  const ElasticCrossingSettings& elastic = *inertial.elastic();
  const WheelParams& wheel = model.simulated_wheel;
  const double M = wheel.mass_kg;
  const double v = wheel.speed_m_per_s;

  // The wheels behind the leading one (a bogie's trailing wheelset).
  std::vector<double> behind_m{0.0};
  if (elastic.bogie) behind_m.push_back(elastic.bogie->axle_spacing_m);
  Wheels wheels;
  ForceRunTrack track;
  std::optional<JenkinsTrack> jenkins_track;
  std::optional<double> start_force_N;
  make_track(model, behind_m, track, wheels, jenkins_track, start_force_N);
  ForceRunVehicle vehicle = make_vehicle(model, wheels);

  const ForceContactGeometry rails(model.force_contact_inputs());
  const ForceRun r{model,
                   hunt_crossley_damping_factor(elastic.contact.restitution),
                   M,
                   v,
                   inertial.force_time_step_s,
                   rails,
                   behind_m};
  CrossingRun run;
  run.vertical_external_force_N = -(inertial.wheel_load_N + M * kStandardGravity_m_per_s2);
  const std::size_t expected = static_cast<std::size_t>(model.end_time_s / r.dt) + 2;
  run.trajectory.samples.reserve(expected);
  run.track_states.reserve(expected);
  std::visit([&](auto& t, auto& load) { step_loop(r, wheels, t, load, run); }, track, vehicle);
  if (DiscreteTrack* beam = std::get_if<DiscreteTrack>(&track)) run.supports = beam->take_support_histories();
  run.discrete_track_equivalent = jenkins_track;
  run.start_contact_force_N = start_force_N;
  return run;
}

}  // namespace railjoint
