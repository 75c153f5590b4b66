#pragma once
// Parameter structs of the kinematic model (thesis chapters 3-4).
// SI units everywhere inside the code; the unit is in every field name.
// Coordinates (the thesis's): x along the track in the direction of travel,
// y lateral (0 on the rail-head centre line), z up. The V bottom of the dip is
// at x = 0; the cut runs along x_cut(y) = y cot(theta).

#include <memory>
#include <numbers>

namespace railjoint {

class ProfileCurve;  // models/profile_curve.h

enum class JointKind {
  inclined,  ///< dipped joint cut at junction angle theta (section 3.3)
  step,      ///< classic step in vertical geometry (section 3.2.2)
};

/// The rail head's top across the track (models/rail_head.h has the formulas).
enum class RailProfile {
  arc,      ///< one circular arc of radius crown_radius_m (0: the thesis's flat head)
  en_60e1,  ///< the standard 60E1 head (EN 13674-1): arcs of 300, 80 and 13 mm
  measured, ///< measured (y, z) points (JointParams::measured_head)
};

/// How each rail end droops towards the joint (models/dip_profile.h has the formulas).
enum class DipShape {
  linear,     ///< straight at slope tan(beta/2) over the whole rail end (the thesis)
  quadratic,  ///< a parabola over dip_length, level beyond it
  cosine,     ///< a quarter cosine wave over dip_length, level beyond it
};

struct JointParams {
  JointKind kind = JointKind::inclined;
  double theta_rad = std::numbers::pi / 6.0;  ///< junction angle between cut and x axis [rad]; pi/2 = square joint
  double beta_rad = 0.03;                     ///< dip angle [rad]; each rail end is inclined by beta/2
  double half_width_m = 0.020;                ///< rail-head half-width b_t [m]
  double length_m = 1.0;                      ///< total length L of the two rail ends together [m]
  double depth_m = 0.05;                      ///< rail-head solid reaches down to z = -depth [m]
  double gap_m = 0.0;                         ///< end-post gap measured normal to the cut [m]
  double step_height_m = 0.001;               ///< step joint: far rail raised by u0 (> 0) or lowered (< 0) [m]
  /// Lateral radius of the rail head's top [m]: a circular arc across y with
  /// its crest on the centre line; 0 = a flat head (the thesis).
  double crown_radius_m = 0.0;
  RailProfile rail_profile = RailProfile::arc;
  std::shared_ptr<const ProfileCurve> measured_head;  ///< RailProfile::measured: (y, z) [m]
  DipShape dip_shape = DipShape::linear;
  double dip_length_m = 0.3;  ///< quadratic and cosine dips: how far from the joint each rail end droops [m]
};

struct WheelParams {
  double radius_m = 0.475;          ///< wheel radius R [m]
  double mass_kg = 750.0;           ///< lumped wheel mass M [kg]
  double width_m = 0.0;             ///< cylinder width b_w [m]; 0 = infinitely thin disc
  double lateral_m = 0.015;         ///< lateral position of the wheel centre plane y_w [m]
  double speed_m_per_s = 50.0;      ///< horizontal (train) speed v [m/s]
  /// tan of the tread's cone angle [-] (0.025 for 1:40; 0 = a cylinder, the
  /// thesis): the radius is R at y_w and R - conicity (y - y_w) across the
  /// tread, larger towards -y (the flange side). Negative reverses the cone.
  double conicity = 0.0;
  /// A measured tread instead of the cone: (y, r) [m], y from the wheel's
  /// plane y_w; radius_m is then its r at y = 0 (the scene reader sets it).
  std::shared_ptr<const ProfileCurve> measured_tread;
};

}  // namespace railjoint
