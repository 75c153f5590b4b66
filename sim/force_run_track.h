#pragma once
// The track under a force run (elastic_crossing_run.h): one of three types,
// each with its state, its step and its energy, behind one interface the run
// is written against once (std::visit picks the type once per run):
//   deflection_m(x), deflection_rate_m_per_s(x), deflection_slope(x)
//       the rail surface's displacement (up +), its rate and slope at x;
//   state_under(x)      the rail and sleeper displacements a sample records;
//   advance(dt)         the first half of a velocity Verlet step: half kick
//                       with the accelerations of the step's start, drift,
//                       rates predicted at the step's end (vertical_mass.h);
//   press(x, F)         the wheel's downward force at x at the step's end;
//   kick_mobility_per_kg(x, y)  the rate at x a unit impulse pressed at y
//                       adds (Verlet's kicks: the implicit damper's W);
//   accelerate(dt/2)    the accelerations at the step's end (the pressed
//                       forces, then cleared) and the second half kick;
//   record_supports()   a sample of the supports' forces (the discrete
//                       track's), once a sample, not each finer step;
//   energy_J(), dissipation_W()  for the run's energy balance.

#include <type_traits>
#include <variant>

#include "sim/discrete_track.h"
#include "sim/force_outcome.h"
#include "sim/lumped_track.h"

namespace railjoint {

/// A rigid track: the rail never moves.
struct RigidTrack {
  double deflection_m(double) const { return 0.0; }
  double deflection_rate_m_per_s(double) const { return 0.0; }
  double deflection_slope(double) const { return 0.0; }
  TrackState state_under(double) const { return {}; }
  void advance(double) {}
  void press(double, double) {}
  double kick_mobility_per_kg(double, double) const { return 0.0; }
  void accelerate(double) {}
  void record_supports() {}
  double energy_J() const { return 0.0; }
  double dissipation_W() const { return 0.0; }
};

/// The alternatives in TrackModel's order (elastic_track_settings.h).
using ForceRunTrack = std::variant<RigidTrack, LumpedTrack, DiscreteTrack>;
static_assert(std::is_same_v<std::variant_alternative_t<static_cast<std::size_t>(TrackModel::lumped), ForceRunTrack>,
                             LumpedTrack> &&
              std::is_same_v<std::variant_alternative_t<static_cast<std::size_t>(TrackModel::discrete), ForceRunTrack>,
                             DiscreteTrack>);

/// A track whose rail mass rings on the Hertz spring after the strike (at
/// ~8.5e3 rad/s on the lumped defaults): its pulse is stepped finer
/// (pulse_window.h). On the rigid track the pulse is the wheel's alone on
/// the spring, a half period of ~2 ms, ~500 steps at 4e-6 s: Verlet's
/// (w dt)^2 / 24 = 1.6e-6 (P1 within 6e-6 on seeded crossings without it,
/// where the window cost 2.0x the steps).
template <class Track>
inline constexpr bool kTrackRings = !std::is_same_v<Track, RigidTrack>;

/// A track whose rail bends: its displacement under a contact depends on
/// where the contact is, and a contact sliding along it moves with its slope.
template <class Track>
inline constexpr bool kTrackBends = std::is_same_v<Track, DiscreteTrack>;

}  // namespace railjoint
