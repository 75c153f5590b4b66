#include "models/joint_flight.h"

#include <algorithm>
#include <cmath>

#include "models/kinematic_trajectory.h"
#include "models/liftoff.h"

namespace railjoint {

JointFlight predict_joint_flight(const JointParams& joint, const WheelParams& wheel,
                                 const ImpactPrediction& prediction, double vertical_load_N) {
  JointFlight flight;
  if (prediction.scenario == ImpactScenario::one || !(vertical_load_N > 0.0)) return flight;
  const double R = wheel.radius_m;
  const double M = wheel.mass_kg;
  const double v = wheel.speed_m_per_s;
  const double g = vertical_load_N / M;
  const double x_K = prediction.contact_A_m.x();
  const double z_K = prediction.contact_A_m.z();

  // The radius angle phi (C ahead of K when > 0) where the wheel leaves.
  double phi = 0.0;
  if (!prediction.on_landing) {
    // At the strike: -alpha, the steepest point of the arc.
    phi = -prediction.alpha_rad;
    if (!(v > pivot_liftoff_speed_m_per_s(M, R, vertical_load_N, phi))) return flight;
  } else {
    // Rolling over the incoming rail's end: from the angle of the incoming
    // slope (the radius is normal to it) to the landing; v_c falls as phi grows.
    const double incoming_top_slope = joint.kind == JointKind::step ? 0.0 : -std::tan(0.5 * joint.beta_rad);
    const double phi_start = -std::atan(incoming_top_slope);
    const double phi_land = prediction.alpha_rad;
    // v_c(phi) = sqrt(W R cos^3 phi / M) = v at cos^3 phi = M v^2 / (W R).
    const double c3 = M * v * v / (vertical_load_N * R);
    if (c3 >= 1.0) {
      phi = phi_start;  // even the top of the arc needs more than the load gives
    } else {
      phi = std::max(phi_start, std::acos(std::cbrt(c3)));
      if (!(phi < phi_land)) return flight;  // it holds on until the landing
    }
  }

  // Leaves with the arc's velocity: (v, -v tan(phi)) at C = K + R (sin, cos).
  const double x0 = x_K + R * std::sin(phi);
  const double z0 = z_K + R * std::cos(phi);
  const double w0 = -v * std::tan(phi);
  const auto parabola_z = [&](double x) {
    const double t = (x - x0) / v;
    return z0 + w0 * t - 0.5 * g * t * t;
  };
  // The path on rails long enough for any flight (the joint's own length is
  // what the caller wants to find out).
  JointParams long_rails = joint;
  long_rails.length_m = 1e4;
  const KinematicPath path(long_rails, wheel);
  const auto clearance = [&](double x) { return parabola_z(x) - path.centre_height_m(x); };
  // March until the parabola is back on or below the path, then bisect. It
  // leaves the arc tangentially and curves less than it: first above.
  const double dx = 1e-4;
  const double x_end = x0 + 0.5 * long_rails.length_m;
  double x_lo = x0;
  double x = x0 + dx;
  while (x < x_end && clearance(x) > 0.0) {
    x_lo = x;
    x += dx;
  }
  if (!(x < x_end)) x = x_end;
  double lo = x_lo, hi = x;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (clearance(mid) > 0.0 ? lo : hi) = mid;
  }
  flight.flies = true;
  flight.liftoff_x_m = x0;
  flight.landing_x_m = hi;
  flight.duration_s = (hi - x0) / v;
  flight.apex_height_m = w0 > 0.0 ? w0 * w0 / (2.0 * g) : 0.0;
  return flight;
}

}  // namespace railjoint
