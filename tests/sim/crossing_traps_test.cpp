// Tests that fail when one of the conditions of sim/DESIGN.md "What the
// simulation must hold to be comparable" is lost: an implicit wheel with
// small margins, settings far from Bullet's defaults, the internal-edge fix
// on the rail meshes, and a wheel started on the incoming slope.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include <gtest/gtest.h>

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>

#include "geometry/rail_joint_mesh.h"
#include "models/kinematic_trajectory.h"
#include "sim/crossing_cases.h"
#include "sim/crossing_world.h"
#include "sim/simulate_crossing.h"

namespace railjoint {
namespace {

// Largest |zdot - zdot_slope| before the wheel gets within 2 mm of the
// impact, zdot_slope = -v tan(beta/2) being the incoming slope's [m/s].
double largest_hop_before_impact_m_per_s(const SimulationResult& r, double beta_rad) {
  const double slope_zdot = -r.model->simulated_wheel.speed_m_per_s * std::tan(0.5 * beta_rad);
  double largest = 0.0;
  for (const WheelSample& s : r.trajectory.samples) {
    if (s.centre_m.x() > r.prediction().impact_wheel_x_m - 0.002) break;
    largest = std::max(largest, std::abs(s.velocity_m_per_s.z() - slope_zdot));
  }
  return largest;
}

TEST(CrossingTraps, WheelIsAnImplicitCylinderWithSmallMargins) {
  // A tessellated wheel with N sides shakes the centre by slopes ~ pi/N, as
  // large as beta/2 for N ~ 100: the wheel must be Bullet's implicit cylinder.
  const CrossingCase c = inclined_crossing("s2", 30.0, 0.015);
  const SimSettings settings;
  WheelParams wheel = c.wheel;
  wheel.width_m = 2.0 * settings.disc_half_width_m;
  const RailJointMesh mesh = build_rail_joint_mesh(c.joint);
  WheelStart start;
  start.centre_m = Eigen::Vector3d(-0.05, wheel.lateral_m, kinematic_centre_height_m(c.joint, wheel, -0.05));
  CrossingWorld world({mesh.incoming, mesh.outgoing}, wheel, settings, kDefaultPreload_N, start);

  const btCollisionShape& shape = world.wheel_shape();
  std::cout << "wheel shape type " << shape.getShapeType() << ", margin " << shape.getMargin() << " m\n";
  EXPECT_EQ(shape.getShapeType(), CYLINDER_SHAPE_PROXYTYPE);
  // Bullet's default margin is 0.04 m, bigger than the 0.78 mm step at the cut.
  EXPECT_LE(shape.getMargin(), 1e-5);
  EXPECT_DOUBLE_EQ(shape.getMargin(), settings.margin_m);
  // Axle along y (Bullet's cylinder axis: round in x-z), as wide as asked.
  const btVector3 half = static_cast<const btCylinderShape&>(shape).getHalfExtentsWithMargin();
  EXPECT_NEAR(half.z(), half.x(), 1e-12);
  EXPECT_NEAR(half.y(), settings.disc_half_width_m, 1e-12);
  // Its size seen from outside: started with its centre R above the incoming
  // slope (kinematic_centre_height_m), the wheel touches the rail to within
  // micrometres (the slop it rests in), not the millimetres a wrong radius or
  // Bullet's 0.04 m default margin would leave.
  double closest_m = std::numeric_limits<double>::infinity();
  for (const ContactSample& contact : world.probe_contacts()) closest_m = std::min(closest_m, std::abs(contact.distance_m));
  std::cout << "closest contact of the wheel at rest: " << closest_m << " m\n";
  EXPECT_LE(closest_m, 1e-5);
}

TEST(CrossingTraps, BulletDefaultSettingsGiveLargeErrors) {
  // Bullet's defaults for this disc: the cylinder's own safe margin
  // (0.1 * half width = 5e-5 m), contact breaking threshold 0.02 m, every
  // reported contact solved, no slop, split impulse only below -0.04 m, soft
  // (speculative) contacts, a fixed step. Even at a fixed 1e-5 s step the
  // jump is off by several percent (measured +8.6 % scenario 2, -4.9 % step
  // up); the defaults of SimSettings give < 0.5 % (crossing_accuracy_test).
  SimSettings bullet;
  bullet.narrow_phase = NarrowPhase::bullet;
  bullet.margin_m = 5e-5;
  bullet.contact_breaking_threshold_m = 0.02;
  bullet.contact_processing_threshold_m = 0.02;
  bullet.split_impulse_threshold_m = -0.04;
  bullet.slop_m = 0.0;
  bullet.hard_contacts = false;
  bullet.time_step_s = bullet.refined_time_step_s = 1e-5;
  bullet.refine_distance_m = 0.0;
  bullet.refine_hold_s = 0.0;
  const auto relative_error = [](const SimulationResult& r) {
    return (r.impulse_Ns() - r.prediction().impulse.exact_Ns) / r.prediction().impulse.exact_Ns;
  };
  for (const CrossingCase& c : {inclined_crossing("scenario2_theta30", 30.0, 0.015), step_crossing("step_up_1mm", 0.001)}) {
    const SimulationResult r = simulate_crossing(c.joint, c.wheel, bullet);
    const double error = relative_error(r);
    std::cout << c.name << " with Bullet's defaults: impact found " << r.impact_found() << ", error " << 100 * error
              << " %\n";
    // Ten times the 0.5 % target would be too close to the measured 4.9 %:
    // 2 % is four times the target and half the smaller measured error.
    ASSERT_TRUE(r.impact_found()) << c.name;
    EXPECT_GT(std::abs(error), 0.02) << c.name;
    // The control: the same case with SimSettings' defaults is within the
    // 0.5 % target, so the large error above is the settings', not a broken run.
    const SimulationResult ours = simulate_crossing(c.joint, c.wheel, SimSettings{});
    ASSERT_TRUE(ours.impact_found()) << c.name;
    EXPECT_LT(std::abs(relative_error(ours)), 5e-3) << c.name;
  }
}

// Largest angle between the contact normals Bullet's own narrow phase finds
// on the incoming rail's top and the top face's normal (sin(beta/2), 0,
// cos(beta/2)), over wheel positions 0.5 mm apart along the rail: the wheel
// crosses the diagonal that splits each quad of the top into two triangles
// [rad].
double largest_top_normal_error_rad(const CrossingCase& c, const SimSettings& settings) {
  const RailJointMesh mesh = build_rail_joint_mesh(c.joint);
  WheelParams wheel = c.wheel;
  wheel.width_m = 0.001;
  const double x_first = -0.45 * c.joint.length_m;
  WheelStart start;
  start.centre_m = Eigen::Vector3d(x_first, wheel.lateral_m, kinematic_centre_height_m(c.joint, wheel, x_first));
  CrossingWorld world({mesh.incoming, mesh.outgoing}, wheel, settings, 0.0, start);
  const Eigen::Vector3d face_normal(std::sin(0.5 * c.joint.beta_rad), 0.0, std::cos(0.5 * c.joint.beta_rad));
  WorldState state = world.state();
  double largest = 0.0;
  int probed = 0;
  for (double x = x_first; x < -0.05; x += 5e-4) {
    state.centre_m = Eigen::Vector3d(x, wheel.lateral_m, kinematic_centre_height_m(c.joint, wheel, x));
    world.restore(state);
    // Only the contacts the solver would take (the resting overlap is the
    // slop); separated ones carry GJK's closest-point normals.
    for (const ContactSample& contact : world.probe_contacts()) {
      if (contact.rail_index != 0 || contact.distance_m > settings.contact_processing_threshold_m) continue;
      largest = std::max(largest, std::acos(std::min(1.0, contact.normal.dot(face_normal))));
      ++probed;
    }
  }
  EXPECT_GT(probed, 500);  // every position has a resting contact on the top
  return largest;
}

TEST(CrossingTraps, InternalEdgeFixKeepsFaceNormalsOnTriangleDiagonals) {
  // Bullet's own narrow phase (the exact one needs no fix: it finds the face
  // wherever a diagonal lies, cylinder_rail_contact.h) with the settings it
  // was tuned with: slop 4 um, solved from 3 um overlap. The wheel resting on
  // the top, placed at 0.5 mm steps along the rail: a contact on a diagonal
  // (an internal edge of the triangle mesh) gets the edge's normal unless the
  // fix replaces it by the face's. On a rail run through the solver such a
  // normal kicked the wheel by up to 1.4e-2 m/s (10.7 N s), depending on
  // where the steps put the wheel on the diagonal.
  const CrossingCase c = inclined_crossing("scenario1_theta45", 45.0, 0.002);
  SimSettings settings;
  settings.narrow_phase = NarrowPhase::bullet;
  settings.slop_m = 4e-6;
  settings.contact_processing_threshold_m = -3e-6;
  const double with_fix = largest_top_normal_error_rad(c, settings);
  settings.internal_edge_fix = false;
  const double without_fix = largest_top_normal_error_rad(c, settings);
  std::cout << "largest angle of a top contact's normal to the face's: " << with_fix << " rad with the fix, "
            << without_fix << " rad without\n";
  // Measured: 2.1e-8 rad with the fix (the penetration solver's noise on a
  // face), 2.5e-2 rad without (the diagonal's own normal, tilted across the
  // rail). 1e-5 rad, a 5e-4 m/s kick at 50 m/s, separates them by more than
  // a factor of 400 on each side.
  EXPECT_LT(with_fix, 1e-5);
  EXPECT_GT(without_fix, 1e-5);
}

TEST(CrossingTraps, WheelStartsOnTheIncomingSlope) {
  // A wheel dropped from above, or at rest, would strike the rail at the start.
  // On the incoming slope (centre line z = -tan(beta/2) x + R / cos(beta/2),
  // the normal offset R turned vertical) moving at zdot = -v tan(beta/2), its
  // only impact is at the joint.
  const CrossingCase c = inclined_crossing("scenario1_theta45", 45.0, 0.002);
  const SimSettings settings;
  const SimulationResult r = simulate_crossing(c.joint, c.wheel, settings);
  const double t = std::tan(0.5 * c.joint.beta_rad);
  const WheelSample& first = r.trajectory.samples.front();
  const double x0 = first.centre_m.x();
  std::cout << "start x " << x0 << " m, z " << first.centre_m.z() << " m, zdot " << first.velocity_m_per_s.z()
            << " m/s; impacts " << r.trajectory.impacts.size() << "\n";
  EXPECT_NEAR(x0, r.prediction().impact_wheel_x_m - settings.approach_distance_m, 1e-12);
  EXPECT_NEAR(first.centre_m.z(), c.wheel.radius_m / std::cos(0.5 * c.joint.beta_rad) - t * x0, 1e-9);
  EXPECT_NEAR(first.velocity_m_per_s.z(), -c.wheel.speed_m_per_s * t, 1e-12);
  ASSERT_EQ(r.trajectory.impacts.size(), 1u);
  EXPECT_NEAR(r.trajectory.impacts.front().wheel_x_m, r.prediction().impact_wheel_x_m, 1e-4);
  // No velocity change before the joint either (the impact detector could
  // miss a slow drift): within 1e-3 m/s of the slope's zdot.
  EXPECT_LT(largest_hop_before_impact_m_per_s(r, c.joint.beta_rad), 1e-3);
}

}  // namespace
}  // namespace railjoint
