#pragma once
// What a force run's contact stage asks the rails: the touching point, the
// normal, the penetration and Hertz's constant there. On the thesis's
// geometry (flat head, cylinder or thin disc, linear dip) the exact narrow
// phase on the meshes (cylinder_rail_contact.h) and the empirical constant
// (hertz_law.h), as before. On any other geometry the analytic tops
// (rail_surface.h: a crowned, 60E1 or measured head, a cone or a measured
// tread, a curved dip, a gap, a step) give the point, and Hertz's constant
// is the elliptical one at that point (models/hertz_ellipse.h), from the
// wheel's slice radius and tread curvature and the head's transverse and
// the dip's longitudinal curvature there: it follows the contact across
// the head and onto the other rail.
//
// Which law where, and why:
//  - a point contact with two finite positive relative curvatures: Hertz's
//    ellipse (Johnson 1985, section 4.2);
//  - a line (a cylinder or a cone on the flat head: B = 0) has no approach
//    constant of its own (the approach of two cylinders depends on their
//    depth, Johnson section 5.1); a thin disc's and a cut edge's curvature is
//    infinite, so Hertz does not apply: the thesis's empirical constant
//    3.86e-8 R^-0.115 there, as track codes use it for a wheel on a head;
//  - a hollow tread that conforms to the head (B <= 0) or a profile whose
//    curvature is undefined (a cusp: the finite difference of its slope
//    exceeds b/a = 1e-6) falls back to the empirical one too; the JSON names
//    the law used at P0 and at P1 (hertz_patch_report.h).
// The normal is the rail surface's, lateral tilt included (the head's
// slope at the point; the wheel moves in x and z only, so the carrier takes
// the lateral part), and the penetration is measured along it.
//
// A given contact.hertz_constant wins everywhere. Where G changes along the
// run (a curved dip's bend, the contact moving from one arc to the next) the
// energy Hertz stores at a fixed penetration changes with it, without work:
// the run's energy balance (energy_surplus_J) counts that too.

#include <optional>
#include <vector>

#include "models/hertz_ellipse.h"
#include "geometry/rail_joint_mesh.h"
#include "models/parameters.h"
#include "sim/sim_settings.h"
#include "sim/hertz_patch_report.h"
#include "sim/rail_surface.h"
#include "sim/trajectory.h"

namespace railjoint {

/// Hertz's law at one touching point.
struct HertzAtContact {
  double hertz_constant_m_per_N2_3 = 0.0;
  std::optional<EllipticalHertz> ellipse;  ///< where the contact is an ellipse
  bool given = false;                      ///< contact.hertz_constant
};

struct ForceContact {
  CylinderContact contact;  ///< normal: the surface's; distance along it
  HertzAtContact hertz;
};

/// What the contact geometry reads of a crossing (CrossingModel holds it all:
/// CrossingModel::force_contact_inputs; taken apart so that the model, which
/// asks for the start's contact, is not read back from here).
struct ForceContactInputs {
  const JointParams& joint;
  const WheelParams& wheel;            ///< as the scene gives it: the empirical constant's radius
  const WheelParams& simulated_wheel;  ///< as simulated: the analytic tops' tread
  const SimSettings& settings;
  const RailJointMesh& rails;
};

class ForceContactGeometry {
 public:
  explicit ForceContactGeometry(const ForceContactInputs& in);

  /// The nearest point of rail 0 or 1 within max_distance_m, and Hertz there.
  ForceContact find(int rail, const WheelCylinder& wheel, double max_distance_m) const;

  /// Hertz's law at a point on rail 0 or 1 (at_edge: on the rail end's cut edge).
  HertzAtContact hertz_at(int rail, const Eigen::Vector3d& point_m, bool at_edge) const;

  bool analytic() const { return analytic_; }

  /// The simulated wheel as the narrow phase takes it, its centre at `centre_m`.
  WheelCylinder wheel_at(const Eigen::Vector3d& centre_m) const;

  /// Whether Hertz's law may switch along the run: on the analytic tops, a
  /// wheel of some width and no given constant, the elliptical law on a face
  /// gives way to the empirical one on a cut edge or the wheel's rim and
  /// back. G jumps there (12 % on 60E1 under a 1:40 cone at a rail end's
  /// edge), and with it the force at a given penetration.
  bool law_can_switch() const;

  /// Whether a contact's law may switch within the next `reach_m` of the
  /// touching point's travel along the track: it is on an edge or a rim
  /// already, or on a face within reach of its rail end's cut.
  bool near_law_switch(int rail, const ForceContact& contact, double reach_m) const;

  /// Hertz's law at the wheel's centre x (the contact's point depends on x
  /// alone: the wheel translates, the track's deflection only lifts the
  /// rail): whether it is the elliptical one there. Empty where the wheel
  /// has no support on that rail.
  std::optional<bool> elliptical_law_at(int rail, const WheelCylinder& wheel) const;

  /// The modulus through which the load on one rail end presses the
  /// surfaces down at the other (rail_end_patch_share.h) [Pa]: E* of the
  /// wheel's and the rails' steel (contact.youngs_modulus, poisson_ratio)
  /// where the rail ends abut (joint.gap 0: one half-space under both, as the
  /// boundary-element solver takes them); 2 E* across an end-post gap, where
  /// each rail end is its own body and only the wheel's surface, half the
  /// pair's compliance for one steel, is shared (the end post's polymer,
  /// ~1/50 of steel's modulus, carries next to nothing across). A given
  /// contact.hertz_constant G sets the bodies' stiffness with it: E* of a
  /// sphere of the wheel's radius R with that G, sqrt(9 / (16 R G^3))
  /// (Johnson 1985, eq. 4.23), so that a stiffer contact is a stiffer body.
  double spanning_coupling_modulus_Pa() const;

 private:
  JointParams joint_;
  WheelParams simulated_wheel_;
  std::vector<RailSurface> rails_;
  bool analytic_ = false;
  HertzMaterial material_;
  std::optional<double> given_m_per_N2_3_;
  double empirical_m_per_N2_3_ = 0.0;
};

/// A rail end's patch semi-length along the track at a penetration: Hertz's
/// ellipse's where the contact is one, else a sphere's sqrt(R delta) with
/// the wheel's rolling radius (rail_end_patch_share.h) [m].
double patch_semi_length_m(const HertzAtContact& hertz, double penetration_m, double wheel_radius_m);

/// The contact a force run starts in, the wheel on its kinematic path with
/// its centre at start_centre_m (before the static sink): its Hertz constant
/// and normal. found = false where the start has no contact within 1 mm.
ForceContact force_start_contact(const ForceContactInputs& in, const Eigen::Vector3d& start_centre_m);

/// Hertz's law at P0 (the run's first row), at P1 (the sample at
/// p1_time_s) and at P2 (the sample at p2_time_s, where there is one), each
/// at the contact bearing the most there, with every bearing rail end's
/// distance from its cut's edge.
ForceHertzPatches force_hertz_patches(const ForceContactInputs& in, const Trajectory& trajectory, double p1_time_s,
                                      std::optional<double> p2_time_s = std::nullopt);

}  // namespace railjoint
