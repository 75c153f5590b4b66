#pragma once
// Where the side view looks while the wheel flies. The view follows the
// wheel's lowest point at a few millimetres of (exaggerated) height; in a
// flight of millimetres, x20, the rails fell out of the bottom of the frame
// and the wheel hung in an empty picture. While the wheel is off the rail
// the view centres between its lowest point and the rail top under it, and a
// render whose window holds a flight the view cannot show at its width is
// drawn wider, one width for all its frames (a zoom that changed from frame
// to frame would read as motion).

#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "geometry/triangle_mesh.h"
#include "renders/frame_schedule.h"
#include "renders/vertical_exaggeration.h"

namespace railjoint {

class SideViewFraming {
 public:
  /// `rails`: the rail meshes (real coordinates; their top faces are read);
  /// `wheel_y_m`: the wheel's lateral position, where the section is cut.
  SideViewFraming(const std::vector<const TriangleMesh*>& rails, double wheel_y_m, double wheel_radius_m,
                  const VerticalExaggeration& exaggeration);

  /// The highest rail top at (x, wheel_y) [m], real; NaN off the rails.
  double rail_top_m(double x_m) const { return top_face_below(x_m).first; }

  /// How far the wheel centred at `centre_m` is off the rail top under it
  /// [m]: its centre's distance from the top face's plane less R (on a slope
  /// the lowest point of a resting wheel lies R (1 / cos gamma - 1) above
  /// the top under the centre, so the vertical gap would not do); NaN off
  /// the rails.
  double clearance_m(const Eigen::Vector3d& centre_m) const;

  /// The drawn point the view centres on for a wheel centred at `centre_m`:
  /// its lowest point, or, in the air (clearance above kTouchingGap_m), the
  /// middle between it and the rail top below.
  Eigen::Vector3d focus(const Eigen::Vector3d& centre_m) const;

  /// The view width [m] that shows the largest drawn gap between the flying
  /// wheel and the rail over `window` in at most kGapShareOfHeight of the height:
  /// `width_m` when it already does.
  double width_for_flights(const Trajectory& trajectory, const FrameWindow& window, double width_m,
                           double aspect) const;

  /// The share of the view's height the largest gap may take.
  static constexpr double kGapShareOfHeight = 0.6;

 private:
  /// The highest top face's height at (x, wheel_y) and the face (nullptr off the rails).
  std::pair<double, const Eigen::Matrix3d*> top_face_below(double x_m) const;
  /// The centre's distance from the face's plane less R [m].
  double clearance_above(const Eigen::Matrix3d& face, const Eigen::Vector3d& centre_m) const;
  /// The drawn height of the rail top under a wheel in the air (clearance
  /// above kTouchingGap_m); nullopt on a rail or off the rails.
  std::optional<double> drawn_top_under_flight(const Eigen::Vector3d& centre_m) const;

  std::vector<Eigen::Matrix3d> tops_;  ///< top-face triangles, a vertex per column [m]
  double wheel_y_m_;
  double wheel_radius_m_;
  VerticalExaggeration exaggeration_;
};

}  // namespace railjoint
