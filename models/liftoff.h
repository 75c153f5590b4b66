#pragma once
// When a loaded wheel stops following the rail: the pivot about a convex
// corner and the ballistic flight after it. The kinematic model glues the
// wheel to the rail; a real wheel is held on it only by its weight and the
// axle load, so it can follow a convex corner (the entry kink of a dip, the
// cut edge it pivots about after a scenario-2 strike, the corner it rolls off
// on the step-down side) only up to a speed. Pure functions, SI units.
//
// Pivot about a corner K, horizontal speed v held by the carrier (bogie):
// let phi be the angle of the radius K -> C (C the wheel centre) from the
// vertical, positive when C is ahead of K. Then
//   x_C = x_K + R sin(phi),  z_C = z_K + R cos(phi),
//   xdot_C = R cos(phi) phidot = v            => phidot = v / (R cos(phi)),
//   zdot_C = -R sin(phi) phidot = -v tan(phi),
//   zddot_C = -v sec^2(phi) phidot = -v^2 / (R cos^3(phi)).
// The corner pushes along the radius (frictionless), N (sin phi, cos phi);
// the carrier takes the horizontal part; the vertical load W = M g + F pulls
// down. Vertically: M zddot = N cos(phi) - W, so
//   N = (W - M v^2 / (R cos^3 phi)) / cos(phi),
// and the wheel stays on the arc while N >= 0:
//   v <= v_c(phi) = sqrt(W R cos^3(phi) / M).
// The demand grows with |phi|: the pivot is lost first where |phi| is largest
// on the arc (the end of the entry kink's arc, phi = beta/2; the start of the
// post-impact pivot, |phi| = alpha; the landing end of the step-down pivot).
// At phi = 0 this is the familiar v^2 / R = W / M.

namespace railjoint {

/// Normal force the corner must supply to keep the wheel on the pivot arc at
/// angle phi (may be negative: the arc cannot be followed there) [N].
/// `vertical_load_N` = W, the wheel's weight plus the axle load on it.
double pivot_contact_force_N(double mass_kg, double radius_m, double vertical_load_N, double speed_m_per_s,
                             double angle_rad);

/// v_c(phi) = sqrt(W R cos^3(phi) / M): above this speed the wheel leaves the
/// corner at angle phi [m/s]. Requires M, R > 0, W >= 0, |phi| < pi/2.
double pivot_liftoff_speed_m_per_s(double mass_kg, double radius_m, double vertical_load_N, double angle_rad);

/// W = M v^2 / (R cos^3(phi)): the vertical load (weight + axle load) that
/// just keeps the wheel on the arc at speed v and angle phi [N].
double pivot_following_load_N(double mass_kg, double radius_m, double speed_m_per_s, double angle_rad);

/// Free flight of the wheel centre after it leaves the rail, horizontal speed
/// v held, under the constant downward acceleration g_eff = W / M, until it
/// meets a straight rail again.
struct BallisticFlight {
  double apex_height_m = 0.0;   ///< highest point above the lift-off point: w0^2 / (2 g_eff) (0 if w0 <= 0) [m]
  double apex_time_s = 0.0;     ///< w0 / g_eff after lift-off (0 if w0 <= 0) [s]
  double flight_time_s = 0.0;   ///< until the centre meets the landing line [s]; NaN if it never does
  double landing_zdot_m_per_s = 0.0;  ///< w0 - g_eff t_flight [m/s]
};

/// The centre leaves with vertical velocity w0 at height z0 = 0; it lands
/// when it is back on the line z = gap + slope * v t that the centre follows
/// on the landing rail (gap: how far that line lies above the lift-off point
/// at lift-off, slope: the landing rail's slope dz/dx). Solves
///   w0 t - g_eff t^2 / 2 = gap + slope v t
/// for the later root:  t = (w' + sqrt(w'^2 - 2 g_eff gap)) / g_eff, w' = w0 - slope v.
BallisticFlight ballistic_flight(double liftoff_zdot_m_per_s, double downward_acceleration_m_per_s2,
                                 double speed_m_per_s, double landing_gap_m, double landing_slope);

}  // namespace railjoint
