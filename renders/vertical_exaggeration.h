#pragma once
// Millimetre geometry under a metre-sized wheel: heights are drawn stretched
// by a factor k about a reference height, z' = z_ref + k (z - z_ref), with x
// and y kept. The SAME affine map is applied to everything drawn: rails,
// wheel (its circle becomes an ellipse k times taller than wide), wheel
// centre, contact and impact points, as in the thesis's exaggerated figures.
// An affine map keeps incidence, tangency and containment, so the drawn wheel
// touches the drawn rails exactly at the (mapped) points where the real wheel
// touches the real rails, and two drawn shapes overlap only where the real
// shapes do. A lift-off of h shows as a gap of k h; a slope s as k s.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace railjoint {

struct VerticalExaggeration {
  double factor = 1.0;         ///< k >= 1
  double reference_z_m = 0.0;  ///< height kept fixed [m]

  double height(double z_m) const { return reference_z_m + factor * (z_m - reference_z_m); }
  Eigen::Vector3d point(const Eigen::Vector3d& p) const { return {p.x(), p.y(), height(p.z())}; }
  /// The map as a 4x4 matrix (column vectors): diag(1, 1, k) plus the shift (1 - k) z_ref.
  Eigen::Matrix4d matrix() const {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m(2, 2) = factor;
    m(2, 3) = (1.0 - factor) * reference_z_m;
    return m;
  }
  /// The drawn lowest point of a wheel of radius R centred at `centre` (axle
  /// along y): the image of the point R below the centre.
  Eigen::Vector3d lowest_wheel_point(const Eigen::Vector3d& centre, double radius_m) const {
    return point(centre - Eigen::Vector3d(0.0, 0.0, radius_m));
  }
};

}  // namespace railjoint
