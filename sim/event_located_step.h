#pragma once
// Event location for impacts (sim/DESIGN.md "How the error floor was removed"):
// Bullet solves a contact only from the step whose start finds it
// closed, with the normal of that configuration. A wheel that overlaps the
// struck corner by d there is d / sin(alpha) past the first touch and its
// normal is turned by about d / (R sin alpha): 0.1-3 % of a scenario-2 jump,
// whatever the step. So a step during which a closing contact passes the
// gap at which the solver takes it is taken again, shortened until it ends
// with that contact just there; the next step's collision detection then
// hands Bullet's solver the contact at the instant of first touch.

#include <array>

#include "sim/step_control.h"
#include "sim/crossing_world.h"

namespace railjoint {

struct EventLocation {
  /// Off for a compliant contact: a spring has no instant of impact to locate.
  bool enabled = true;
  /// Bullet's solver takes a contact from this signed gap down [m]
  /// (sim.contact_processing_threshold): a located step ends with the
  /// struck contact's gap in [solved_from - tolerance, solved_from].
  double solved_from_m = 0.0;
  /// [m]: as wide as the solving gap is far from the touch (at least
  /// 1e-12 m), so the struck contact is solved at a gap between 0 and
  /// solved_from (impact_location).
  double tolerance_m = 1e-11;
  /// A contact counts as closing above this speed along its normal [m/s]
  /// (resting and pivoting contacts are held at zero by the solver).
  double closing_speed_m_per_s = 0.0;
};

struct LocatedStep {
  double dt_s = 0.0;          ///< the step taken [s] (shorter than asked when an event was located)
  bool located = false;       ///< the step ends at a first touch
  WheelSample sample;         ///< world.sample() after the step
  std::vector<ContactSample> contacts_now;  ///< world.probe_contacts() after the step
};

/// What both crossings locate: contacts closing faster than
/// kClosingSpeedFraction of the speed [m/s], from the gap at which the
/// solver takes them (sim.contact_processing_threshold); off when compliant.
EventLocation impact_location(const SimSettings& settings, double speed_m_per_s, bool compliant);

/// Per rail (ContactSample::rail_index): the smallest signed gap, less
/// solved_from, of its contacts closing faster than the closing speed;
/// +infinity for a rail with none, or one the wheel is already on
/// (RailsInContact) [m].
inline constexpr int kMaxRails = 2;
using RailGaps = std::array<double, kMaxRails>;
RailGaps closing_gaps_beyond_solving_m(const std::vector<ContactSample>& contacts, const EventLocation& location,
                                       RailsInContact engaged);

/// Steps `world` by dt_s, or less so as to end at the first touch of a
/// contact that closes during the step. `contacts_at_start` are the probed
/// contacts of the current configuration (the previous call's contacts_now).
LocatedStep step_locating_impacts(CrossingWorld& world, double dt_s, const std::vector<ContactSample>& contacts_at_start,
                                  const EventLocation& location, RailsInContact engaged);

}  // namespace railjoint
