#pragma once
// The force model of an inertial run (issue "forces on an elastic track"):
// which law the wheel-rail contact follows, what the track under the rail is
// (lumped, or the discrete track of discrete_track.h) and what rides on the
// wheel. Plain header without Bullet or Eigen, read by scenes/ from the
// [contact], [track] and [vehicle] sections. Empty track and vehicle parts
// mean a rigid track and a constant static wheel load.

#include <optional>

#include "sim/bogie_settings.h"

namespace railjoint {

/// Hertz's law F = (delta / G)^(3/2) on each wheel-rail contact's
/// penetration delta, with Hunt and Crossley's dissipation.
struct HertzContactSettings {
  /// G [m/N^(2/3)]. Empty: Hertz's elliptical constant at the touching
  /// point where the contact is an ellipse (sim/force_contact_geometry.h),
  /// else 3.86e-8 R^-0.115 (hertz_law.h).
  std::optional<double> hertz_constant_m_per_N2_3;
  /// The steels of wheel and rail (contact.youngs_modulus, poisson_ratio).
  double youngs_modulus_Pa = 210e9;
  double poisson_ratio = 0.3;
  /// Coefficient of restitution of an isolated impact under the law [-]
  /// (Hunt and Crossley's form, its damping factor solved for it: hertz_law.h):
  /// 1 is pure Hertz (Jenkins's model), 0 plastic (a rebound below 1e-4).
  double restitution = 1.0;
};

/// What carries the rail at a sleeper, for both elastic tracks: a pad
/// (spring and damper) to a sleeper mass on ballast to the ground, per rail
/// seat. Defaults: the pad, half-sleeper and ballast values sim/DESIGN.md
/// ("Forces on an elastic track") gives as one published set.
struct TrackSupportSettings {
  double pad_stiffness_N_per_m = 200e6;
  double pad_damping_N_s_per_m = 28e3;
  double sleeper_mass_kg = 140.0;  ///< half sleeper: one rail's share
  double ballast_stiffness_N_per_m = 40e6;
  double ballast_damping_N_s_per_m = 47e3;
  /// Pad and ballast in series: the support's static stiffness [N/m].
  double series_stiffness_N_per_m() const {
    return pad_stiffness_N_per_m * ballast_stiffness_N_per_m / (pad_stiffness_N_per_m + ballast_stiffness_N_per_m);
  }
};

/// Jenkins's lumped vertical track: both rail ends as one rigid rail mass on
/// one support, vertical motion only. Default rail mass: one 0.6 m sleeper
/// bay of 60E1 rail (60.2 kg/m).
struct LumpedTrackSettings {
  double rail_mass_kg = 60.2 * 0.6;
  TrackSupportSettings support;
};

/// What a Timoshenko rail adds to Euler's (track.beam = "timoshenko",
/// timoshenko_rail.h): shear deformation and rotary inertia. Defaults: 60E1.
struct TimoshenkoRailSettings {
  double shear_modulus_Pa = 81e9;  ///< rail steel: E / (2 (1 + nu)) = 210 GPa / 2.6
  /// kappa [-]: the share of the section that carries shear as if uniformly
  /// strained; 0.4 is the value track models take for a flat-bottom rail
  /// bending vertically (web-dominated shear, about the web's share of A).
  double shear_coefficient = 0.4;
  double section_area_m2 = 7.670e-3;    ///< 60E1 (EN 13674-1: 76.70 cm^2)
  double rotary_inertia_kg_m = 0.2385;  ///< rho I per metre: 7850 kg/m^3 x 3.038e-5 m^4 (mu I / A)
  /// kappa G A [N]: the rail's shear stiffness (2.485e8 N on the defaults).
  double shear_stiffness_N() const { return shear_coefficient * shear_modulus_Pa * section_area_m2; }
};

/// The discrete track (discrete_track.h): the rail a beam on a support every
/// sleeper_spacing, the joint midway between two sleepers.
struct DiscreteTrackSettings {
  double bending_stiffness_N_m2 = 6.38e6;  ///< EI of 60E1: E 210 GPa x I 3.038e-5 m^4
  double mass_per_length_kg_per_m = 60.2;  ///< 60E1
  double sleeper_spacing_m = 0.6;
  TrackSupportSettings support;
  /// The joint bars' rotational stiffness [N m/rad]: 0 a free hinge; empty:
  /// continuous rail (EI / h like every other node).
  std::optional<double> joint_bending_stiffness_N_m_per_rad;
  /// Empty: an Euler-Bernoulli rail (track.beam = "euler", the default);
  /// else Timoshenko's.
  std::optional<TimoshenkoRailSettings> timoshenko;
  /// Rail nodes per sleeper bay (track.nodes_per_bay), even: a sleeper at
  /// the bay's middle node, the joint at a bay's end. A numerical choice:
  /// the rail's grid error falls as 1 / nodes^2 (docs/forces.md, "The
  /// rail's grid"), the stable step as 1 / nodes^2 too.
  int nodes_per_bay = 8;
};

/// A sprung mass on the primary suspension above the wheel (the wheel is
/// the unsprung mass). Its weight is the static wheel load: it carries
/// sim.wheel_load down through the suspension, so P0 stays wheel_load + M g.
struct PrimarySuspensionSettings {
  double primary_stiffness_N_per_m = 1e6;
  double primary_damping_N_s_per_m = 10e3;
  /// Empty: wheel_load / g, the mass whose weight the suspension carries.
  std::optional<double> sprung_mass_kg;
};

/// Which track a force run has, in the order of ForceRunTrack's alternatives
/// (force_run_track.h).
enum class TrackModel { rigid, lumped, discrete };

/// The name the scene's [track] model key and every output use for it.
constexpr const char* track_model_name(TrackModel model) {
  switch (model) {
    case TrackModel::lumped:
      return "lumped";
    case TrackModel::discrete:
      return "discrete";
    case TrackModel::rigid:
      break;
  }
  return "rigid";
}

struct ElasticCrossingSettings {
  HertzContactSettings contact;
  /// The track under the rail: at most one of the two; both empty: rigid.
  std::optional<LumpedTrackSettings> track;             ///< [track] model = "lumped"
  std::optional<DiscreteTrackSettings> discrete_track;  ///< [track] model = "discrete"
  std::optional<PrimarySuspensionSettings> vehicle;  ///< empty: constant static load
  /// [vehicle] model = "bogie" (only with the discrete track): a second
  /// wheel axle_spacing behind the first, both under the bogie.
  std::optional<BogieSettings> bogie;
  /// How far behind the leading wheel the last wheel runs [m]: the rails,
  /// the track and the run reach that much further (crossing_model.cpp).
  double trailing_reach_m() const { return bogie ? bogie->axle_spacing_m : 0.0; }
  TrackModel track_model() const {
    return track ? TrackModel::lumped : discrete_track ? TrackModel::discrete : TrackModel::rigid;
  }
  /// Simulated time after the predicted impact [s] when sim.run_out_time is
  /// not given: the P2 peak comes about a quarter period of the wheel and
  /// track on the ballast after it (6.4 ms at the default track's 30 Hz);
  /// one whose P2 comes in the run's last 10 % is suspect (self_check.h).
  double run_out_time_s = 0.02;
};

/// Zero-phase low-pass cut-off that separates P2 from P1 [Hz]
/// (force_peaks.h): P2 modes lie at 30-100 Hz, P1 at 0.3-2 kHz.
inline constexpr double kP2CutoffFrequency_Hz = 150.0;

}  // namespace railjoint
