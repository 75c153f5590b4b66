#include "renders/side_view.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "renders/close_view_labels.h"
#include "renders/palette.h"
#include "renders/slab_section.h"
#include "renders/text_overlay.h"

namespace railjoint {

namespace {

// Gap between the drawn section face of the rails and the wheel's near face
// [m]: the section lies this far behind the wheel face, so where the wheel
// overlaps the rails (a simulated penetration) the wheel is drawn in front
// and the overlap shows. 2 um moves the section's corner at the cut by
// 2 um cot(theta) (0.04 px at 0.12 m over 1280 px, theta = 30 deg) and is
// ten steps of the 24-bit depth buffer over the side view's 3.5 m depth range.
constexpr double kSectionInset_m = 2e-6;

}  // namespace

SideView::SideView(const RenderSettings& settings_in, const RailJointMesh& rails, const TriangleMesh& wheel,
                   const Trajectory& trajectory)
    : CrossingView(settings_in, rails, wheel, trajectory),
      framing_({&rails.incoming, &rails.outgoing}, setup_.wheel_y_m, setup_.wheel_radius_m, setup_.exaggeration) {
  if (!(setup_.wheel_half_width_m > kSectionInset_m)) {
    throw std::invalid_argument("render: the side view cuts the rails to the wheel's width, but the wheel mesh is " +
                                std::to_string(2.0 * setup_.wheel_half_width_m) +
                                " m wide; give it a positive width (> 4 um)");
  }
  RenderSettings& settings = setup_.settings;
  if (settings.follow_wheel && !settings.view_width_m) {
    const double aspect = static_cast<double>(settings.width_px) / static_cast<double>(settings.height_px);
    const double width_m = visible_width_m(settings, setup_.framing);
    const double needed_m = framing_.width_for_flights(setup_.trajectory, setup_.window, width_m, aspect);
    if (needed_m > width_m) settings.view_width_m = needed_m;
  }
  const double view_width_m = visible_width_m(settings, setup_.framing);
  px_per_m_ = static_cast<double>(settings.width_px) / view_width_m;

  // Datum: a thin light line at the reference height (the height the
  // exaggeration keeps), BEHIND the rails and the wheel, so it shows only
  // where nothing else is and never reads as part of the geometry. Lengths
  // are read off the scale bars instead of ticks. Drawn coordinates.
  std::vector<MeshVertex> datum;
  const double y_datum = setup_.rail_box_m.max().y() + 0.001;
  const double zr = settings.reference_z_m;
  const double line_half = 0.5 * (1.0 / px_per_m_);
  const GroundPlane& g = setup_.ground;
  add_quad(datum, {g.x_lo_m, y_datum, zr - line_half}, {g.x_hi_m, y_datum, zr - line_half},
           {g.x_hi_m, y_datum, zr + line_half}, {g.x_lo_m, y_datum, zr + line_half}, palette::datum);

  const double y_lo = setup_.wheel_y_m - setup_.wheel_half_width_m + kSectionInset_m;
  const double y_hi = setup_.wheel_y_m + setup_.wheel_half_width_m;
  setup_.open_gl(rail_pair_vertices(cut_convex_solid_to_slab(rails.incoming, y_lo, y_hi),
                                    cut_convex_solid_to_slab(rails.outgoing, y_lo, y_hi)),
                 wheel, view_width_m, px_per_m_);
  ground_ = setup_.gl->add_triangles(setup_.checker_ground());
  datum_ = setup_.gl->add_triangles(datum);
  path_ = setup_.gl->add_line_strip(setup_.lowest_point_path());
}

Eigen::Vector3d SideView::focus_at(double t_s) const {
  if (!setup_.settings.follow_wheel) return setup_.fixed_focus_m;
  return framing_.focus(sample_at(setup_.trajectory, t_s).centre_m);
}

FrameDrawList SideView::frame_at(double t_s) const {
  const WheelSample sample = sample_at(setup_.trajectory, t_s);
  const Camera camera = camera_at(t_s);
  FrameDrawList list;
  SceneDraw scene = close_scene(camera, ground_);
  scene.meshes.push_back({datum_});
  // Everything through the same map, the wheel included.
  setup_.append_close_wheel(scene, sample);
  const Eigen::Matrix4f e = setup_.exaggeration.matrix().cast<float>();
  scene.line_strips.push_back(setup_.path_up_to(path_, e, t_s));
  append_contact_markers(scene, setup_, t_s, sample, setup_.close_marker_px(), true);
  list.scenes.push_back(scene);

  const double y = setup_.wheel_y_m, half = setup_.wheel_half_width_m, zr_mm = setup_.settings.reference_z_m * 1e3;
  std::string lines = format_label("side view, rails cut to the wheel's width (y = %.2f .. %.2f mm)\n",
                                   (y - half) * 1e3, (y + half) * 1e3);
  lines += format_label("heights x%g about z = %g mm, the wheel too (drawn as an ellipse)\n",
                        setup_.exaggeration.factor, zr_mm);
  lines += "magenta: contact points   orange ring: impact point\n";
  lines += format_label("green: path of the wheel's lowest point   grey line: z = %g mm", zr_mm);
  append_close_view_labels(list, setup_, t_s, sample, camera, px_per_m_, setup_.impact_within_one_frame(t_s), lines,
                           true);
  return list;
}

}  // namespace railjoint
