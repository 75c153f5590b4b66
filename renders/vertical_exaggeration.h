#pragma once
// Millimetre geometry under a metre-sized wheel: heights are drawn stretched
// by a factor k about a reference height, z' = z_ref + k (z - z_ref), for the
// rails, contact points and impact points alike. The wheel is drawn rigid
// (an exaggerated circle would be a tall ellipse); its centre rides R above
// the exaggerated profile: a centre R above a rail point is drawn R above the
// drawn point, z_c' = z_ref + R + k (z_c - R - z_ref). So a wheel touching the
// rail directly below its centre is drawn touching it, and a lift-off of h
// shows as a gap of k h. (Off-centre contacts, e.g. the cut edge ahead of the
// centre in scenario 2, are drawn k-fold steeper than they are, like the
// thesis's exaggerated figures.)

#include <Eigen/Core>

namespace railjoint {

struct VerticalExaggeration {
  double factor = 1.0;          ///< k >= 1
  double reference_z_m = 0.0;   ///< height kept fixed [m]
  double wheel_radius_m = 0.0;  ///< R of the drawn wheel [m]

  Eigen::Vector3d point(const Eigen::Vector3d& p) const {
    return {p.x(), p.y(), reference_z_m + factor * (p.z() - reference_z_m)};
  }
  Eigen::Vector3d wheel_centre(const Eigen::Vector3d& c) const {
    return {c.x(), c.y(), reference_z_m + wheel_radius_m + factor * (c.z() - wheel_radius_m - reference_z_m)};
  }
};

}  // namespace railjoint
