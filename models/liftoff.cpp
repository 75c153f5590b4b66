#include "models/liftoff.h"

#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

namespace railjoint {

namespace {
void check_pivot(double mass_kg, double radius_m, double angle_rad) {
  assert(mass_kg > 0.0 && radius_m > 0.0 && std::abs(angle_rad) < std::numbers::pi / 2.0);
  (void)mass_kg;
  (void)radius_m;
  (void)angle_rad;
}
}  // namespace

double pivot_contact_force_N(double mass_kg, double radius_m, double vertical_load_N, double speed_m_per_s,
                             double angle_rad) {
  check_pivot(mass_kg, radius_m, angle_rad);
  const double c = std::cos(angle_rad);
  return (vertical_load_N - mass_kg * speed_m_per_s * speed_m_per_s / (radius_m * c * c * c)) / c;
}

double pivot_liftoff_speed_m_per_s(double mass_kg, double radius_m, double vertical_load_N, double angle_rad) {
  check_pivot(mass_kg, radius_m, angle_rad);
  assert(vertical_load_N >= 0.0);
  const double c = std::cos(angle_rad);
  return std::sqrt(vertical_load_N * radius_m * c * c * c / mass_kg);
}

double pivot_following_load_N(double mass_kg, double radius_m, double speed_m_per_s, double angle_rad) {
  check_pivot(mass_kg, radius_m, angle_rad);
  const double c = std::cos(angle_rad);
  return mass_kg * speed_m_per_s * speed_m_per_s / (radius_m * c * c * c);
}

BallisticFlight ballistic_flight(double liftoff_zdot_m_per_s, double downward_acceleration_m_per_s2,
                                 double speed_m_per_s, double landing_gap_m, double landing_slope) {
  assert(downward_acceleration_m_per_s2 > 0.0);
  const double g = downward_acceleration_m_per_s2;
  const double w0 = liftoff_zdot_m_per_s;
  BallisticFlight flight;
  if (w0 > 0.0) {
    flight.apex_time_s = w0 / g;
    flight.apex_height_m = w0 * w0 / (2.0 * g);
  }
  // Height above the landing line: h(t) = -gap + w' t - g t^2 / 2 with
  // w' = w0 - slope v; the flight ends at its later zero.
  const double w = w0 - landing_slope * speed_m_per_s;
  const double discriminant = w * w - 2.0 * g * landing_gap_m;
  if (discriminant < 0.0) {
    flight.flight_time_s = std::numeric_limits<double>::quiet_NaN();
    flight.landing_zdot_m_per_s = std::numeric_limits<double>::quiet_NaN();
    return flight;
  }
  flight.flight_time_s = (w + std::sqrt(discriminant)) / g;
  if (!(flight.flight_time_s >= 0.0)) flight.flight_time_s = std::numeric_limits<double>::quiet_NaN();
  flight.landing_zdot_m_per_s = w0 - g * flight.flight_time_s;
  return flight;
}

}  // namespace railjoint
