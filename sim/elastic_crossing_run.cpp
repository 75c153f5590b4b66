#include "sim/elastic_crossing_run.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include <btBulletDynamicsCommon.h>

#include "sim/cylinder_rail_contact.h"
#include "sim/discrete_track.h"
#include "sim/hertz_law.h"
#include "sim/run_interrupt.h"

namespace railjoint {

namespace {

// One body of the force run: Bullet integrates it; it moves along z only
// (the wheel's horizontal speed is set by the carrier every step) and is
// paired with nothing, so Bullet finds no contacts and solves none.
struct VerticalBody {
  std::unique_ptr<btCollisionShape> shape;
  std::unique_ptr<btRigidBody> body;

  VerticalBody(btDiscreteDynamicsWorld& world, std::unique_ptr<btCollisionShape> body_shape, double mass_kg,
               const btVector3& position_m, const btVector3& velocity_m_per_s)
      : shape(std::move(body_shape)) {
    btVector3 inertia(0, 0, 0);
    shape->calculateLocalInertia(mass_kg, inertia);
    btTransform transform;
    transform.setIdentity();
    transform.setOrigin(position_m);
    btRigidBody::btRigidBodyConstructionInfo info(mass_kg, nullptr, shape.get(), inertia);
    info.m_startWorldTransform = transform;
    info.m_linearDamping = 0.0;
    info.m_angularDamping = 0.0;
    body = std::make_unique<btRigidBody>(info);
    body->setActivationState(DISABLE_DEACTIVATION);
    body->setLinearFactor(btVector3(0, 0, 1));
    body->setAngularFactor(btVector3(0, 0, 0));
    world.addRigidBody(body.get(), 1, 0);  // mask 0: no broadphase pair, no Bullet contact
    body->setLinearVelocity(velocity_m_per_s);
  }
  double z_m() const { return body->getWorldTransform().getOrigin().z(); }
  double zdot_m_per_s() const { return body->getLinearVelocity().z(); }
  void push_up(double force_N) { body->applyCentralForce(btVector3(0, 0, force_N)); }
};

// A spring and damper between a body above and one below (or the ground):
// the force it pushes them apart with [N], from its compression [m] and the
// compression's rate [m/s].
double spring_damper_N(double stiffness_N_per_m, double damping_N_s_per_m, double compression_m,
                       double compression_rate_m_per_s) {
  return stiffness_N_per_m * compression_m + damping_N_s_per_m * compression_rate_m_per_s;
}

}  // namespace

CrossingRun run_elastic_crossing(const CrossingModel& model) {
  const SimSettings& settings = model.settings;
  const InertialSettings& inertial = *settings.inertial();
  const ElasticCrossingSettings& elastic = *inertial.elastic();
  const WheelParams& wheel = model.simulated_wheel;
  const double G = model.hertz_constant_m_per_N2_3;
  // The damping factor that makes an isolated impact rebound at e (hertz_law.h).
  const double damping_factor = hunt_crossley_damping_factor(elastic.contact.restitution);
  const double M = wheel.mass_kg;
  const double g = kStandardGravity_m_per_s2;
  const double v = wheel.speed_m_per_s;

  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
  world.setGravity(btVector3(0, 0, 0));  // weights are applied as forces below, with the loads

  const Eigen::Vector3d& c0 = model.start.centre_m;
  VerticalBody wheel_body(world,
                          std::make_unique<btCylinderShape>(btVector3(wheel.radius_m, 0.5 * wheel.width_m, wheel.radius_m)),
                          M, btVector3(c0.x(), c0.y(), c0.z()), btVector3(v, 0, model.start.vertical_velocity_m_per_s));
  // The track: the rail mass and the sleeper (displacements from the unloaded
  // track; their own weights rest on the springs before the wheel comes and
  // change nothing in the motion).
  std::unique_ptr<VerticalBody> rail;
  std::unique_ptr<VerticalBody> sleeper;
  // Or the discrete track, stepped beside Bullet by the same scheme
  // (discrete_track.h), at rest under the wheel's static load.
  std::unique_ptr<DiscreteTrack> beam;
  if (elastic.discrete_track) {
    beam = std::make_unique<DiscreteTrack>(*elastic.discrete_track, model.discrete_track_half_length_m);
    beam->rest_under(inertial.wheel_load_N + M * g, model.start_contact_x_m, v);
  }
  if (elastic.track) {
    const LumpedTrackSettings& t = *elastic.track;
    rail = std::make_unique<VerticalBody>(world, std::make_unique<btSphereShape>(0.05), t.rail_mass_kg,
                                          btVector3(0, 0, model.start_track.rail_z_m), btVector3(0, 0, 0));
    sleeper = std::make_unique<VerticalBody>(world, std::make_unique<btSphereShape>(0.05), t.support.sleeper_mass_kg,
                                             btVector3(0, 0, model.start_track.sleeper_z_m), btVector3(0, 0, 0));
  }
  // The sprung mass above the wheel, moving with it at the start; its
  // suspension carries the static wheel load.
  std::unique_ptr<VerticalBody> sprung;
  double sprung_start_z_m = 0.0;
  if (elastic.vehicle) {
    const double mass_kg = elastic.vehicle->sprung_mass_kg.value_or(inertial.wheel_load_N / g);
    sprung_start_z_m = c0.z() + 1.0;  // any height: the suspension's compression is counted from the start
    sprung = std::make_unique<VerticalBody>(world, std::make_unique<btSphereShape>(0.05), mass_kg,
                                            btVector3(c0.x(), c0.y(), sprung_start_z_m),
                                            btVector3(0, 0, model.start.vertical_velocity_m_per_s));
  }

  const std::array<const TriangleMesh*, 2> rails = {&model.rails.incoming, &model.rails.outgoing};
  // Hunt-Crossley needs the rate at which each rail's contact was made; a
  // contact the run starts in was made at rest (pure Hertz).
  std::array<bool, 2> touching = {false, false};
  std::array<double, 2> impact_rate = {0.0, 0.0};
  // Where each rail's contact was a step ago: on a bending beam the rail
  // surface under a contact that slides along it moves by its slope too.
  std::array<double, 2> previous_contact_x = {0.0, 0.0};
  std::array<bool, 2> had_contact = {false, false};

  CrossingRun run;
  run.vertical_external_force_N = -(inertial.wheel_load_N + M * g);
  const double dt = inertial.force_time_step_s;
  const auto record = [&](double time_s, std::vector<ContactSample> contacts) {
    WheelSample s;
    s.time_s = time_s;
    const btVector3& p = wheel_body.body->getWorldTransform().getOrigin();
    const btVector3& u = wheel_body.body->getLinearVelocity();
    s.centre_m = Eigen::Vector3d(p.x(), p.y(), p.z());
    s.velocity_m_per_s = Eigen::Vector3d(u.x(), u.y(), u.z());
    // Semi-implicit Euler: the velocity a step ends with moved the wheel over
    // that step, so it belongs to the step's middle.
    s.velocity_time_s = std::max(0.0, time_s - 0.5 * dt);
    s.spin_angle_rad = (p.x() - c0.x()) / wheel.radius_m;
    s.spin_rate_rad_per_s = u.x() / wheel.radius_m;
    s.contacts = std::move(contacts);
    run.trajectory.samples.push_back(std::move(s));
    TrackState track;
    if (rail) {
      track.rail_z_m = rail->z_m();
      track.sleeper_z_m = sleeper->z_m();
    }
    if (beam) {
      track.rail_z_m = beam->deflection_m(p.x());
      track.sleeper_z_m = beam->nearest_sleeper_m(p.x());
    }
    if (sprung) track.sprung_z_m = sprung->z_m() - sprung_start_z_m;
    run.track_states.push_back(track);
  };
  const std::size_t expected = static_cast<std::size_t>(model.end_time_s / dt) + 2;
  run.trajectory.samples.reserve(expected);
  run.track_states.reserve(expected);

  double time_s = 0.0;
  double max_penetration_m = 0.0;
  // The energy balance (CrossingRun::energy_surplus_J): the energy at the
  // start, and what the carrier put in and the dampers took out since.
  double start_energy_J = 0.0;
  double carrier_work_J = 0.0;
  double dissipated_J = 0.0;
  bool first_step = true;
  while (time_s < model.end_time_s - 1e-12) {
    const double step_s = std::min(dt, model.end_time_s - time_s);
    wheel_body.body->setLinearVelocity(btVector3(v, 0, wheel_body.zdot_m_per_s()));  // the carrier holds the speed
    const btVector3& p = wheel_body.body->getWorldTransform().getOrigin();
    const Eigen::Vector3d wheel_velocity(v, 0, wheel_body.zdot_m_per_s());
    // The rail's displacement and its rate where it meets the wheel: one rigid
    // rail mass moves as a whole; the beam of the discrete track bends, so
    // its deflection is read at the contact (found once with the deflection
    // under the centre, then again with the one at that contact: the beam's
    // slope, ~1e-3, moves the point by far less than its own size).
    const auto rail_z_at = [&](double x_m) { return beam ? beam->deflection_m(x_m) : rail ? rail->z_m() : 0.0; };
    const auto rail_zdot_at = [&](double x_m) {
      return beam ? beam->deflection_rate_m_per_s(x_m) : rail ? rail->zdot_m_per_s() : 0.0;
    };

    // Hertz on each rail's nearest point, the rail moved by its displacement.
    WheelCylinder cylinder;
    cylinder.radius_m = wheel.radius_m;
    cylinder.half_width_m = 0.5 * wheel.width_m;
    std::vector<ContactSample> contacts;
    double wheel_force_z_N = 0.0;
    double hertz_energy_J_now = 0.0;
    double carrier_power_W = 0.0;
    double contact_damping_W = 0.0;
    for (std::size_t r = 0; r < rails.size(); ++r) {
      cylinder.centre_m = Eigen::Vector3d(p.x(), p.y(), p.z() - rail_z_at(p.x()));
      CylinderContact contact = cylinder_rail_contact(cylinder, *rails[r], settings.contact_breaking_threshold_m);
      if (beam && contact.found) {
        cylinder.centre_m.z() = p.z() - rail_z_at(contact.point_on_rail_m.x());
        contact = cylinder_rail_contact(cylinder, *rails[r], settings.contact_breaking_threshold_m);
      }
      const double contact_x_m = contact.point_on_rail_m.x();
      const double rail_z = rail_z_at(contact_x_m);
      // d/dt w(x_c(t)) = dw/dt + x_c' dw/dx: the contact slides at the wheel's
      // speed on a face, stays put on a corner it pivots about.
      const double contact_speed_m_per_s =
          contact.found && had_contact[r] ? (contact_x_m - previous_contact_x[r]) / step_s : v;
      const double slope_rate_m_per_s = beam ? contact_speed_m_per_s * beam->deflection_slope(contact_x_m) : 0.0;
      const double rail_zdot = rail_zdot_at(contact_x_m) + slope_rate_m_per_s;
      had_contact[r] = contact.found;
      previous_contact_x[r] = contact_x_m;
      const bool penetrating = contact.found && contact.distance_m < 0.0;
      if (!contact.found) {
        touching[r] = false;
        continue;
      }
      const double separating_rate = wheel_velocity.dot(contact.normal) - rail_zdot * contact.normal.z();
      if (penetrating && !touching[r]) impact_rate[r] = time_s > 0.0 ? std::max(0.0, -separating_rate) : 0.0;
      touching[r] = penetrating;
      const double penetration_m = -contact.distance_m;
      max_penetration_m = std::max(max_penetration_m, penetration_m);
      const double force_N = penetrating ? hunt_crossley_force_N(G, damping_factor, penetration_m,
                                                                 -separating_rate, impact_rate[r])
                                         : 0.0;
      wheel_force_z_N += force_N * contact.normal.z();
      if (beam) beam->press(contact_x_m, force_N * contact.normal.z());
      // The carrier cancels the contact's push along x, working at -F n_x v,
      // and drags the contact along the bent rail, F n_z x_c' dw/dx (the
      // normal is taken untilted by the rail's ~1e-3 slope); Hunt and
      // Crossley's part beyond Hertz's takes F_damping d(delta)/dt.
      hertz_energy_J_now += hertz_energy_J(G, penetration_m);
      carrier_power_W += force_N * (contact.normal.z() * slope_rate_m_per_s - contact.normal.x() * v);
      if (penetrating) contact_damping_W += (force_N - hertz_force_N(G, penetration_m)) * -separating_rate;
      ContactSample c;
      c.point_on_rail_m = contact.point_on_rail_m + Eigen::Vector3d(0, 0, rail_z);
      c.normal = contact.normal;
      c.distance_m = contact.distance_m;
      c.normal_impulse_Ns = force_N * step_s;
      c.rail_index = static_cast<int>(r);
      c.normal_velocity_m_per_s = separating_rate;
      contacts.push_back(c);
    }

    // The first row is the state the run starts in with that state's contact
    // forces (the static load on the rail), which the first step carries:
    // without them every history began at zero force.
    if (first_step) record(0.0, contacts);

    // Mechanical energy at the step's start, for the energy balance: kinetic
    // (vertical; the held x speed's is constant), the loads' potentials, the
    // springs', Hertz's; and what the dampers take.
    const double wheel_zdot = wheel_body.zdot_m_per_s();
    double energy_J = 0.5 * M * wheel_zdot * wheel_zdot + M * g * p.z() + hertz_energy_J_now;
    double damping_W = contact_damping_W;

    // The loads: the wheel's weight and the static wheel load, which the
    // suspension carries when there is one (preloaded by it, so the sprung
    // mass, loaded by the same force, starts at rest).
    double wheel_load_N = inertial.wheel_load_N;
    if (sprung) {
      const PrimarySuspensionSettings& s = *elastic.vehicle;
      const double compression_m = (sprung_start_z_m - c0.z()) - (sprung->z_m() - p.z());
      const double compression_rate_m_per_s = wheel_zdot - sprung->zdot_m_per_s();
      wheel_load_N += spring_damper_N(s.primary_stiffness_N_per_m, s.primary_damping_N_s_per_m, compression_m,
                                      compression_rate_m_per_s);
      sprung->push_up(wheel_load_N - inertial.wheel_load_N);
      const double mass_kg = 1.0 / sprung->body->getInvMass();
      energy_J += inertial.wheel_load_N * (compression_m + sprung->z_m()) +
                  0.5 * s.primary_stiffness_N_per_m * compression_m * compression_m +
                  0.5 * mass_kg * sprung->zdot_m_per_s() * sprung->zdot_m_per_s();
      damping_W += s.primary_damping_N_s_per_m * compression_rate_m_per_s * compression_rate_m_per_s;
    } else {
      energy_J += inertial.wheel_load_N * p.z();
    }
    wheel_body.push_up(wheel_force_z_N - M * g - wheel_load_N);
    if (rail) {
      const LumpedTrackSettings& t = *elastic.track;
      const TrackSupportSettings& support = t.support;
      const double pad_m = sleeper->z_m() - rail->z_m();
      const double pad_rate_m_per_s = sleeper->zdot_m_per_s() - rail->zdot_m_per_s();
      const double pad_N =
          spring_damper_N(support.pad_stiffness_N_per_m, support.pad_damping_N_s_per_m, pad_m, pad_rate_m_per_s);
      const double ballast_N = spring_damper_N(support.ballast_stiffness_N_per_m, support.ballast_damping_N_s_per_m,
                                               -sleeper->z_m(), -sleeper->zdot_m_per_s());
      rail->push_up(-wheel_force_z_N + pad_N);
      sleeper->push_up(-pad_N + ballast_N);
      energy_J += 0.5 * t.rail_mass_kg * rail->zdot_m_per_s() * rail->zdot_m_per_s() +
                  0.5 * support.sleeper_mass_kg * sleeper->zdot_m_per_s() * sleeper->zdot_m_per_s() +
                  0.5 * support.pad_stiffness_N_per_m * pad_m * pad_m +
                  0.5 * support.ballast_stiffness_N_per_m * sleeper->z_m() * sleeper->z_m();
      damping_W += support.pad_damping_N_s_per_m * pad_rate_m_per_s * pad_rate_m_per_s +
                   support.ballast_damping_N_s_per_m * sleeper->zdot_m_per_s() * sleeper->zdot_m_per_s();
    }
    if (beam) {
      energy_J += beam->energy_J();
      damping_W += beam->dissipation_W();
    }
    if (first_step) start_energy_J = energy_J;
    first_step = false;
    run.energy_surplus_J =
        std::max(run.energy_surplus_J, energy_J - start_energy_J - carrier_work_J + dissipated_J);
    carrier_work_J += carrier_power_W * step_s;
    dissipated_J += damping_W * step_s;

    world.stepSimulation(step_s, 0, step_s);
    if (beam) beam->step(step_s);
    time_s += step_s;
    ++run.steps;
    poll_run_interrupt(run.steps);
    if (step_s <= settings.refined_time_step_s * (1 + 1e-9)) ++run.refined_steps;
    record(time_s, std::move(contacts));
  }
  if (run.trajectory.samples.empty()) record(0.0, {});  // a run of no step: its start alone
  run.max_penetration_m = max_penetration_m;
  return run;
}

}  // namespace railjoint
