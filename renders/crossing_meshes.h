#pragma once
// The triangles the crossing renderer uploads, in REAL coordinates (metres,
// before the vertical exaggeration, which each view applies as its model
// matrix): rails coloured by face, the wheel body with smooth rim normals,
// the marks that show the wheel's spin, the ground, the straightedge over the
// joint and the running band on the rail head. No GL here.

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "geometry/rail_joint_mesh.h"
#include "geometry/triangle_mesh.h"
#include "renders/offscreen_renderer.h"
#include "sim/trajectory.h"

namespace railjoint {

/// A recorded contact is drawn when its gap is below this [m]. The simulation
/// also reports contacts that are still open (up to its contact breaking
/// threshold, 2 mm by default) so that it sees a gap closing; those touch
/// nothing yet. Touching contacts overlap by the slop (4 um) or less.
inline constexpr double kTouchingGap_m = 1e-6;

void add_triangle(std::vector<MeshVertex>& out, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                  const Eigen::Vector3d& c, const Eigen::Vector3f& colour);
void add_quad(std::vector<MeshVertex>& out, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
              const Eigen::Vector3d& c, const Eigen::Vector3d& d, const Eigen::Vector3f& colour);

/// Both rails' triangles, coloured by face tag (renders/palette.h); the
/// outgoing rail's non-running faces a shade darker. Winding kept.
std::vector<MeshVertex> rail_pair_vertices(const TriangleMesh& incoming, const TriangleMesh& outgoing);

/// The wheel mesh (centred at the origin, axle along y) with the rim's
/// normals radial at every vertex, so the light runs round the tread as on a
/// cylinder rather than facet by facet. dish = 0: flat faces; dish > 0: the
/// face normals tilt outwards by dish times the relative radius, so the light
/// grades across the face like a dished wheel web (shading only; the shape
/// stays the simulated one). Winding kept.
std::vector<MeshVertex> wheel_body_vertices(const TriangleMesh& wheel, double dish);

/// The joint line: a red strip `width_m` wide lying just on the rail tops
/// along the top edge of the incoming rail's cut face (the cut as it shows
/// on the rail head from above). Empty when the rail has no cut face.
std::vector<MeshVertex> cut_line_on_top(const RailJointMesh& rails, double width_m);

/// Marks on both faces of the wheel (in its own frame) for a view of the
/// whole wheel: a darker tyre band over the outer 10 % of the radius, a hub,
/// and a bar with a knob on its +x end that shows the spin. face_offset_m:
/// how far outside the faces they lie, so the face never hides them.
std::vector<MeshVertex> whole_wheel_marks(double radius_m, double half_width_m, double face_offset_m);

/// Marks for the close views (side, top, the perspective inset), where the
/// wheel's bottom is drawn k-fold stretched at px_m metres a pixel: dark
/// ticks just inside the rim, one sixth of the view apart (every fourth
/// longer: 36 px, else 20 px, 3 px wide, 3 px in from the rim), and a dark
/// bar with a knob on its +x end, on both faces. rim_inner_m: the inscribed
/// radius of the wheel polygon.
std::vector<MeshVertex> contact_view_wheel_marks(double radius_m, double rim_inner_m, double half_width_m,
                                                 double face_offset_m, double view_width_m, double px_m, double k);

/// Where a straightedge laid on both rail ends touches them, and the largest
/// gap under it: the dip a track engineer measures (a 1 m straightedge over a
/// dipped joint).
struct Straightedge {
  Eigen::Vector3d start_m = Eigen::Vector3d::Zero();  ///< highest point of the incoming rail's top
  Eigen::Vector3d end_m = Eigen::Vector3d::Zero();    ///< highest point of the outgoing rail's top
  double dip_m = 0.0;                                 ///< largest gap between it and the rail tops
};
/// Throws std::invalid_argument when a rail has no top face.
Straightedge straightedge_over(const RailJointMesh& rails);

/// A square bar along the straightedge at y = y_m, `thickness_m` square, hanging below the line.
std::vector<MeshVertex> straightedge_bar(const Straightedge& edge, double y_m, double thickness_m);

/// The running band: the strips of the rail head the wheel has touched up to
/// t_s (contacts closer than kTouchingGap_m of the samples at or before t_s), y_lo_m .. y_hi_m
/// wide, as flat quads at height z_m (above the rail tops, seen from above).
/// A flight leaves a gap in it.
std::vector<MeshVertex> running_band(const Trajectory& trajectory, double t_s, double y_lo_m, double y_hi_m,
                                     double z_m);

}  // namespace railjoint
