#include "sim/elastic_crossing_run.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <variant>

#include <btBulletDynamicsCommon.h>

#include "sim/force_contact_geometry.h"
#include "sim/force_run_track.h"
#include "sim/force_run_vehicle.h"
#include "sim/hertz_law.h"
#include "sim/run_interrupt.h"
#include "sim/vertical_body.h"

namespace railjoint {

namespace {

// What a rail's contact remembers from one step to the next. Hunt-Crossley
// needs the rate at which the contact was made (a contact the run starts in
// was made at rest: pure Hertz); on a bending beam the rail surface under a
// contact that slides along it moves by its slope too.
struct RailContactMemory {
  bool touching = false;
  double impact_rate_m_per_s = 0.0;
  bool had_contact = false;
  double previous_contact_x_m = 0.0;
};

// What the contact stage hands the rest of the step.
struct ContactForces {
  std::vector<ContactSample> contacts;
  double wheel_force_z_N = 0.0;
  double hertz_energy_J = 0.0;
  double carrier_power_W = 0.0;    // the carrier's work rate on the contacts
  double contact_damping_W = 0.0;  // Hunt and Crossley's part beyond Hertz's
};

// The energy balance (CrossingRun::energy_surplus_J): the energy at the
// start, and what the carrier put in and the dampers took out since.
struct EnergyLedger {
  bool started = false;
  double start_energy_J = 0.0;
  double carrier_work_J = 0.0;
  double dissipated_J = 0.0;
};

// What a run reads and does not change: the model, the wheel's body and the
// constants of its loop.
struct ForceRun {
  const CrossingModel& model;
  double damping_factor;  // makes an isolated impact rebound at e (hertz_law.h)
  double M;
  double v;
  double dt;
  VerticalBody& wheel;
  const ForceContactGeometry& rails;  // the touching point, normal and Hertz's constant
};

// (model) => (the track in its start state, its bodies in the world). Built
// in place: the discrete track's factorisation does not move.
void make_track(btDiscreteDynamicsWorld& world, const CrossingModel& model, ForceRunTrack& track) {
  const InertialSettings& inertial = *model.settings.inertial();
  const ElasticCrossingSettings& elastic = *inertial.elastic();
  if (elastic.discrete_track) {
    // At rest under the wheel's static load.
    DiscreteTrack& beam = track.emplace<DiscreteTrack>(*elastic.discrete_track, model.discrete_track_half_length_m);
    beam.rest_under(inertial.wheel_load_N + model.simulated_wheel.mass_kg * kStandardGravity_m_per_s2,
                    model.start_contact_x_m, model.simulated_wheel.speed_m_per_s);
  }
  if (elastic.track) track.emplace<LumpedTrack>(world, *elastic.track, model.start_track);
}

// (model) => (the load on the wheel: constant, or a sprung mass in the world).
ForceRunVehicle make_vehicle(btDiscreteDynamicsWorld& world, const CrossingModel& model) {
  const InertialSettings& inertial = *model.settings.inertial();
  const ElasticCrossingSettings& elastic = *inertial.elastic();
  ForceRunVehicle vehicle(ConstantLoad{inertial.wheel_load_N});
  if (elastic.vehicle) {
    const double mass_kg = elastic.vehicle->sprung_mass_kg.value_or(inertial.wheel_load_N / kStandardGravity_m_per_s2);
    const Eigen::Vector3d& c0 = model.start.centre_m;
    vehicle.emplace<SprungMass>(world, *elastic.vehicle, inertial.wheel_load_N, mass_kg,
                                btVector3(c0.x(), c0.y(), c0.z()), model.start.vertical_velocity_m_per_s);
  }
  return vehicle;
}

// (wheel position and velocity, track displacement, memory) => (contacts,
// their forces on the wheel, the track pressed, memory, max penetration).
// Hertz (Hunt-Crossley) on each rail's nearest point, with Hertz's constant
// there (force_contact_geometry.h), the rail moved by the track's
// displacement. On a bending track the displacement is read at the contact:
// found once with the deflection under the centre, then again with the one
// at that contact (the beam's slope, ~1e-3, moves the point by far less than
// its own size).
template <class Track>
ContactForces contact_stage(const ForceRun& r, Track& track, double time_s, double step_s,
                            std::array<RailContactMemory, 2>& memory, double& max_penetration_m) {
  const btVector3& p = r.wheel.body->getWorldTransform().getOrigin();
  const Eigen::Vector3d wheel_velocity(r.v, 0, r.wheel.zdot_m_per_s());
  const double breaking_m = r.model.settings.contact_breaking_threshold_m;
  WheelCylinder cylinder;
  cylinder.radius_m = r.model.simulated_wheel.radius_m;
  cylinder.half_width_m = 0.5 * r.model.simulated_wheel.width_m;
  ContactForces out;
  for (std::size_t k = 0; k < memory.size(); ++k) {
    RailContactMemory& m = memory[k];
    const int rail = static_cast<int>(k);
    cylinder.centre_m = Eigen::Vector3d(p.x(), p.y(), p.z() - track.deflection_m(p.x()));
    ForceContact found = r.rails.find(rail, cylinder, breaking_m);
    if constexpr (kTrackBends<Track>) {
      if (found.contact.found) {
        cylinder.centre_m.z() = p.z() - track.deflection_m(found.contact.point_on_rail_m.x());
        found = r.rails.find(rail, cylinder, breaking_m);
      }
    }
    const CylinderContact& contact = found.contact;
    const double G = found.hertz.hertz_constant_m_per_N2_3;
    const double contact_x_m = contact.point_on_rail_m.x();
    const double rail_z = track.deflection_m(contact_x_m);
    // d/dt w(x_c(t)) = dw/dt + x_c' dw/dx: the contact slides at the wheel's
    // speed on a face, stays put on a corner it pivots about.
    double slope_rate_m_per_s = 0.0;
    if constexpr (kTrackBends<Track>) {
      const double contact_speed_m_per_s =
          contact.found && m.had_contact ? (contact_x_m - m.previous_contact_x_m) / step_s : r.v;
      slope_rate_m_per_s = contact_speed_m_per_s * track.deflection_slope(contact_x_m);
    }
    const double rail_zdot = track.deflection_rate_m_per_s(contact_x_m) + slope_rate_m_per_s;
    m.had_contact = contact.found;
    m.previous_contact_x_m = contact_x_m;
    const bool penetrating = contact.found && contact.distance_m < 0.0;
    if (!contact.found) {
      m.touching = false;
      continue;
    }
    const double separating_rate = wheel_velocity.dot(contact.normal) - rail_zdot * contact.normal.z();
    if (penetrating && !m.touching) m.impact_rate_m_per_s = time_s > 0.0 ? std::max(0.0, -separating_rate) : 0.0;
    m.touching = penetrating;
    const double penetration_m = -contact.distance_m;
    max_penetration_m = std::max(max_penetration_m, penetration_m);
    const double force_N = penetrating ? hunt_crossley_force_N(G, r.damping_factor, penetration_m,
                                                               -separating_rate, m.impact_rate_m_per_s)
                                       : 0.0;
    out.wheel_force_z_N += force_N * contact.normal.z();
    track.press(contact_x_m, force_N * contact.normal.z());
    // The carrier cancels the contact's push along x, working at -F n_x v,
    // and drags the contact along the bent rail, F n_z x_c' dw/dx (the
    // normal is taken untilted by the rail's ~1e-3 slope); Hunt and
    // Crossley's part beyond Hertz's takes F_damping d(delta)/dt.
    out.hertz_energy_J += hertz_energy_J(G, penetration_m);
    out.carrier_power_W += force_N * (contact.normal.z() * slope_rate_m_per_s - contact.normal.x() * r.v);
    if (penetrating) out.contact_damping_W += (force_N - hertz_force_N(G, penetration_m)) * -separating_rate;
    ContactSample c;
    c.point_on_rail_m = contact.point_on_rail_m + Eigen::Vector3d(0, 0, rail_z);
    c.normal = contact.normal;
    c.distance_m = contact.distance_m;
    c.normal_impulse_Ns = force_N * step_s;
    c.rail_index = static_cast<int>(k);
    c.normal_velocity_m_per_s = separating_rate;
    out.contacts.push_back(c);
  }
  return out;
}

// (wheel, vehicle, track, contact forces) => (energy at the step's start,
// what the dampers take) for the balance: kinetic (vertical; the held x
// speed's is constant), the loads' potentials, the springs', Hertz's.
template <class Track, class Vehicle>
void energy_stage(const ForceRun& r, const Track& track, const Vehicle& vehicle, const ContactForces& forces,
                  double step_s, EnergyLedger& ledger, CrossingRun& run) {
  const double z = r.wheel.z_m();
  const double zdot = r.wheel.zdot_m_per_s();
  double energy_J = 0.5 * r.M * zdot * zdot + r.M * kStandardGravity_m_per_s2 * z + forces.hertz_energy_J;
  double damping_W = forces.contact_damping_W;
  energy_J += vehicle.energy_J(z, zdot);
  damping_W += vehicle.dissipation_W(z, zdot);
  energy_J += track.energy_J();
  damping_W += track.dissipation_W();
  if (!ledger.started) ledger.start_energy_J = energy_J;
  ledger.started = true;
  run.energy_surplus_J =
      std::max(run.energy_surplus_J, energy_J - ledger.start_energy_J - ledger.carrier_work_J + ledger.dissipated_J);
  ledger.carrier_work_J += forces.carrier_power_W * step_s;
  ledger.dissipated_J += damping_W * step_s;
}

// (wheel, track, vehicle) => (a sample and its track state in the run).
template <class Track, class Vehicle>
void record_stage(const ForceRun& r, const Track& track, const Vehicle& vehicle, double time_s,
                  std::vector<ContactSample> contacts, CrossingRun& run) {
  WheelSample s;
  s.time_s = time_s;
  const btVector3& p = r.wheel.body->getWorldTransform().getOrigin();
  const btVector3& u = r.wheel.body->getLinearVelocity();
  const Eigen::Vector3d& c0 = r.model.start.centre_m;
  const double radius_m = r.model.simulated_wheel.radius_m;
  s.centre_m = Eigen::Vector3d(p.x(), p.y(), p.z());
  s.velocity_m_per_s = Eigen::Vector3d(u.x(), u.y(), u.z());
  // Semi-implicit Euler: the velocity a step ends with moved the wheel over
  // that step, so it belongs to the step's middle.
  s.velocity_time_s = std::max(0.0, time_s - 0.5 * r.dt);
  s.spin_angle_rad = (p.x() - c0.x()) / radius_m;
  s.spin_rate_rad_per_s = u.x() / radius_m;
  s.contacts = std::move(contacts);
  run.trajectory.samples.push_back(std::move(s));
  TrackState state = track.state_under(p.x());
  state.sprung_z_m = vehicle.sprung_z_m();
  run.track_states.push_back(state);
}

// The stepping loop, written once and compiled for each track and vehicle.
template <class Track, class Vehicle>
void step_loop(const ForceRun& r, btDiscreteDynamicsWorld& world, Track& track, Vehicle& vehicle, CrossingRun& run) {
  const SimSettings& settings = r.model.settings;
  double time_s = 0.0;
  double max_penetration_m = 0.0;
  std::array<RailContactMemory, 2> memory;
  EnergyLedger ledger;
  while (time_s < r.model.end_time_s - 1e-12) {
    const double step_s = std::min(r.dt, r.model.end_time_s - time_s);
    // (wheel zdot) => (wheel velocity): the carrier holds the speed.
    r.wheel.body->setLinearVelocity(btVector3(r.v, 0, r.wheel.zdot_m_per_s()));
    ContactForces forces = contact_stage(r, track, time_s, step_s, memory, max_penetration_m);
    // The first row is the state the run starts in with that state's contact
    // forces (the static load on the rail), which the first step carries:
    // without them every history began at zero force.
    if (run.trajectory.samples.empty()) record_stage(r, track, vehicle, 0.0, forces.contacts, run);
    // (wheel, vehicle) => (the load on the wheel; the sprung mass's force).
    const double wheel_load_N = vehicle.load_N(r.wheel.z_m(), r.wheel.zdot_m_per_s());
    energy_stage(r, track, vehicle, forces, step_s, ledger, run);
    // (contact forces, weight, load) => (force on the wheel).
    r.wheel.push_up(forces.wheel_force_z_N - r.M * kStandardGravity_m_per_s2 - wheel_load_N);
    // (every body, its forces) => (every body a step later): Bullet's
    // semi-implicit Euler for its bodies, the track's own for its arrays.
    track.step(step_s);
    world.stepSimulation(step_s, 0, step_s);
    time_s += step_s;
    ++run.steps;
    poll_run_interrupt(run.steps);
    if (step_s <= settings.refined_time_step_s * (1 + 1e-9)) ++run.refined_steps;
    record_stage(r, track, vehicle, time_s, std::move(forces.contacts), run);
  }
  if (run.trajectory.samples.empty()) record_stage(r, track, vehicle, 0.0, {}, run);  // a run of no step: its start alone
  run.max_penetration_m = max_penetration_m;
}

}  // namespace

CrossingRun run_elastic_crossing(const CrossingModel& model) {
  const InertialSettings& inertial = *model.settings.inertial();
  const ElasticCrossingSettings& elastic = *inertial.elastic();
  const WheelParams& wheel = model.simulated_wheel;
  const double M = wheel.mass_kg;
  const double v = wheel.speed_m_per_s;

  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
  world.setGravity(btVector3(0, 0, 0));  // weights are applied as forces, with the loads

  const Eigen::Vector3d& c0 = model.start.centre_m;
  VerticalBody wheel_body(world,
                          std::make_unique<btCylinderShape>(btVector3(wheel.radius_m, 0.5 * wheel.width_m, wheel.radius_m)),
                          M, btVector3(c0.x(), c0.y(), c0.z()), btVector3(v, 0, model.start.vertical_velocity_m_per_s));
  ForceRunTrack track;
  make_track(world, model, track);
  ForceRunVehicle vehicle = make_vehicle(world, model);

  const ForceContactGeometry rails(model);
  const ForceRun r{model,
                   hunt_crossley_damping_factor(elastic.contact.restitution),
                   M,
                   v,
                   inertial.force_time_step_s,
                   wheel_body,
                   rails};
  CrossingRun run;
  run.vertical_external_force_N = -(inertial.wheel_load_N + M * kStandardGravity_m_per_s2);
  const std::size_t expected = static_cast<std::size_t>(model.end_time_s / r.dt) + 2;
  run.trajectory.samples.reserve(expected);
  run.track_states.reserve(expected);
  std::visit([&](auto& t, auto& load) { step_loop(r, world, t, load, run); }, track, vehicle);
  return run;
}

}  // namespace railjoint
