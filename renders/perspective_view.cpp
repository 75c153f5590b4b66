#include "renders/perspective_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "geometry/wheel_mesh.h"
#include "renders/palette.h"
#include "renders/text_overlay.h"
#include "renders/wheel_tessellation.h"

namespace railjoint {

namespace {

// The overview looks from behind the wheel (the incoming side), on the same
// side as the side view (y < 0, travel left to right) and from above: at
// about 30 deg to the rail it sees the wheel's face as a disc and the rail
// head's top with the cut across it. The inset looks at the contact from the
// same side, lower and more along the rail, so the V, the cut and the struck
// corner read in 3-D.
const Eigen::Vector3d kOverviewToEye = Eigen::Vector3d(-0.50, -0.80, 0.42).normalized();
const Eigen::Vector3d kInsetToEye = Eigen::Vector3d(-0.75, -0.80, 0.50).normalized();
const Eigen::Vector3f kOverviewToLight = Eigen::Vector3f(-0.30f, -0.60f, 0.75f).normalized();
const double kOverviewFovy_rad = 30.0 * std::numbers::pi / 180.0;
const double kInsetFovy_rad = 40.0 * std::numbers::pi / 180.0;
// Visible width of the inset at the contact: wider than the side view's
// default so both rail ends' slopes show beside the step.
constexpr double kInsetViewWidth_m = 0.16;

// Share of the image width the overview takes; the rest is the panel with
// the inset above the legend.
constexpr double kOverviewShare = 0.64;

// Point j of 24 round a wheel of radius R centred at c, y_m off its mid-plane.
Eigen::Vector3d rim_point(const Eigen::Vector3d& c, double radius_m, int j, double y_m) {
  const double phi = 2.0 * std::numbers::pi * j / 24.0;
  return c + Eigen::Vector3d(radius_m * std::cos(phi), y_m, radius_m * std::sin(phi));
}

}  // namespace

PerspectiveView::PerspectiveView(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
                                 const Trajectory& trajectory)
    : CrossingView(settings, rails, wheel, trajectory) {
  const CrossingSetup& s = setup_;
  const int w = s.settings.width_px, h = s.settings.height_px;
  const int pad = std::max(2, h / 90);
  const int overview_w = static_cast<int>(std::lround(kOverviewShare * w));
  const int panel_w = std::max(1, w - overview_w - 2 * pad);
  const int inset_h = std::max(1, static_cast<int>(std::lround(0.56 * h)) - pad);
  overview_rect_ = {0, 0, overview_w, h};
  inset_rect_ = {overview_w + pad, pad, panel_w, inset_h};
  legend_rect_ = {overview_w + pad, pad + inset_h + pad, panel_w, std::max(1, h - inset_h - 3 * pad)};
  const double view_width_m = s.settings.view_width_m.value_or(kInsetViewWidth_m);
  const double px_per_m = static_cast<double>(inset_rect_.width) / view_width_m;

  // The straightedge on both rail ends, beside the rail head on the side the
  // overview camera looks from, so its lower edge and the rail's top edge
  // show the dip as the gap between them; and the cut line on the rail head.
  const double bar_m = 0.006;
  std::vector<MeshVertex> joint_marks =
      straightedge_bar(s.straightedge, s.rail_box_real_m.min().y() - 0.5 * bar_m - 0.002, bar_m);
  const std::vector<MeshVertex> cut = cut_line_on_top(rails, 0.004);
  joint_marks.insert(joint_marks.end(), cut.begin(), cut.end());

  // Frame the wheel over the window and the rails within 1.3 R of it.
  const double radius = s.wheel_radius_m;
  std::vector<Eigen::Vector3d> points;
  const double reach = 1.3 * radius;
  const double rx_lo = std::max(s.rail_box_real_m.min().x(), s.window_x_lo_m - reach);
  const double rx_hi = std::min(s.rail_box_real_m.max().x(), s.window_x_hi_m + reach);
  for (double x : {rx_lo, rx_hi}) {
    for (double y : {s.rail_box_real_m.min().y(), s.rail_box_real_m.max().y()}) {
      for (double z : {s.rail_box_real_m.min().z(), s.rail_top_max_m}) points.emplace_back(x, y, z);
    }
  }
  for (double t : {s.window.t_start_s, s.window.t_end_s}) {
    const Eigen::Vector3d c = sample_at(s.trajectory, t).centre_m;
    for (int j = 0; j < 24; ++j) {
      for (double side : {-1.0, 1.0}) points.push_back(rim_point(c, radius, j, side * s.wheel_half_width_m));
    }
  }
  Eigen::AlignedBox3d bounds = s.rail_box_real_m;
  for (const auto& p : points) bounds.extend(p);
  const double aspect = static_cast<double>(overview_rect_.width) / static_cast<double>(overview_rect_.height);
  overview_camera_ = fit_perspective_camera(points, kOverviewToEye, kOverviewFovy_rad, aspect, 0.06, bounds);

  setup_.open_gl(rail_pair_vertices(rails.incoming, rails.outgoing), wheel, view_width_m, px_per_m);
  // The overview's camera stands still: one plain ground quad instead of
  // the checker (whose edges cost anti-aliasing and PNG bytes for nothing).
  const GroundPlane& g = s.ground;
  std::vector<MeshVertex> plain;
  add_quad(plain, {g.x_lo_m, -g.y_half_m, g.z_m}, {g.x_hi_m, -g.y_half_m, g.z_m}, {g.x_hi_m, g.y_half_m, g.z_m},
           {g.x_lo_m, g.y_half_m, g.z_m}, palette::ground_a);
  plain_ground_ = setup_.gl->add_triangles(plain);
  whole_marks_ = setup_.gl->add_triangles(whole_wheel_marks(radius, s.wheel_half_width_m, s.face_offset_m));
  joint_marks_ = setup_.gl->add_triangles(joint_marks);
  // The whole wheel is drawn a few hundred pixels across: as many sides as
  // keep its outline within a quarter pixel of the circle there (about 90
  // at 720p), not the contact view's 1,400. Its drawn radius is taken as
  // 1.5 times the farthest projected rim point from the projected centre:
  // the margin covers the rim seen at a slant (an ellipse with semi-axes
  // a > b is flattest at the ends of b, with radius a^2 / b; the overview
  // sees the wheel with a / b about 1.1).
  double drawn_radius_px = 0.0;
  for (double t : {s.window.t_start_s, s.window.t_end_s}) {
    const Eigen::Vector3d c = sample_at(s.trajectory, t).centre_m;
    for (int j = 0; j < 24; ++j) {
      const Eigen::Vector2f rim_px = project_overview(rim_point(c, radius, j, 0.0));
      drawn_radius_px = std::max(drawn_radius_px, static_cast<double>((rim_px - project_overview(c)).norm()));
    }
  }
  WheelParams coarse;
  coarse.radius_m = radius;
  coarse.width_m = 2.0 * s.wheel_half_width_m;
  overview_wheel_sides_ = polygon_sides_for_radius_px(1.5 * std::max(drawn_radius_px, 1.0));
  dished_wheel_ = setup_.gl->add_triangles(wheel_body_vertices(build_wheel_mesh(coarse, overview_wheel_sides_, 0.0), 0.3));
  path_ = setup_.gl->add_line_strip(setup_.lowest_point_path());
}

Camera PerspectiveView::camera_at(double t_s) const {
  const double aspect = static_cast<double>(inset_rect_.width) / static_cast<double>(inset_rect_.height);
  return look_at_focus(focus_at(t_s), kInsetToEye, kInsetFovy_rad, aspect,
                       setup_.settings.view_width_m.value_or(kInsetViewWidth_m), setup_.framing.scene_bounds);
}

Eigen::Vector2f PerspectiveView::project_overview(const Eigen::Vector3d& point_m) const {
  return project_to_pixel(overview_camera_, overview_rect_, point_m);
}

SceneDraw PerspectiveView::overview_scene(double t_s, const WheelSample& sample) const {
  SceneDraw scene = scene_seen_by(overview_camera_, kOverviewToLight);
  scene.orthographic = false;
  scene.viewport = overview_rect_;
  const Eigen::Matrix4f pose = wheel_pose(sample);
  MeshDraw body{dished_wheel_, pose};
  body.cull_back_faces = true;
  body.specular = 0.45f;  // the highlight runs round the rim
  // Nearest first, so the depth test rejects what they hide before it is shaded.
  const MeshDraw rails = setup_.rails_draw(Eigen::Matrix4f::Identity());
  scene.meshes = {body, {whole_marks_, pose}, rails, {joint_marks_}, {plain_ground_}};
  append_contact_markers(scene, setup_, t_s, sample,
                         std::max(5.0f, static_cast<float>(setup_.settings.height_px) / 110.0f), false);
  return scene;
}

SceneDraw PerspectiveView::inset_scene(double t_s, const WheelSample& sample) const {
  SceneDraw scene = scene_seen_by(camera_at(t_s), kOverviewToLight);
  scene.viewport = inset_rect_;
  // Too close to the contact to see the ground.
  const Eigen::Matrix4f e = setup_.exaggeration.matrix().cast<float>();
  scene.meshes = {setup_.rails_draw(e)};
  setup_.append_close_wheel(scene, sample);
  scene.line_strips.push_back(setup_.path_up_to(path_, e, t_s));
  append_contact_markers(scene, setup_, t_s, sample, setup_.close_marker_px(), true);
  return scene;
}

FrameDrawList PerspectiveView::frame_at(double t_s) const {
  const WheelSample sample = sample_at(setup_.trajectory, t_s);
  FrameDrawList list;
  // The overview's and the inset's colour, cleared once for both (the panel
  // behind the inset and the legend is laid with the labels).
  list.background = palette::background;
  list.scenes.push_back(overview_scene(t_s, sample));
  list.scenes.push_back(inset_scene(t_s, sample));
  append_labels(list, t_s, sample, setup_.impact_within_one_frame(t_s));
  return list;
}

void PerspectiveView::append_labels(FrameDrawList& list, double t_s, const WheelSample& sample,
                                    const ImpactEvent* current) const {
  const float h = static_cast<float>(setup_.settings.height_px);
  const PixelRect& inset = inset_rect_;
  const PixelRect& legend = legend_rect_;
  const float line = std::max(1.0f, h / 360.0f);  // 2 px at 720p

  // The panel right of the overview, round the inset and behind the legend:
  // four rectangles, laid first so that everything else lies on it.
  const float x0 = static_cast<float>(inset.x), y0 = static_cast<float>(inset.y);
  const float x1 = x0 + static_cast<float>(inset.width), y1 = y0 + static_cast<float>(inset.height);
  const float panel_x0 = static_cast<float>(overview_rect_.x + overview_rect_.width);
  const float w = static_cast<float>(setup_.settings.width_px);
  append_rectangle(list.overlay, panel_x0, 0.0f, w, y0, palette::panel);
  append_rectangle(list.overlay, panel_x0, y0, x0, y1, palette::panel);
  append_rectangle(list.overlay, x1, y0, w, y1, palette::panel);
  append_rectangle(list.overlay, panel_x0, y1, w, h, palette::panel);

  // A dark frame round the inset, and its caption inside its top-left corner.
  append_outline(list.overlay, x0 - line, y0 - line, x1 + line, y1 + line, line, palette::text);

  // Where the inset looks, outlined in the overview and joined to the inset
  // (a call-out), from the inset camera's visible width around its focus.
  const Camera inset_camera = camera_at(t_s);
  const Eigen::Vector3d focus = focus_at(t_s);
  const double half = 0.5 * inset_camera.visible_width_m;
  float bx0 = 1e9f, by0 = 1e9f, bx1 = -1e9f, by1 = -1e9f;
  for (double dx : {-half, half}) {
    for (double y : {setup_.rail_box_real_m.min().y(), setup_.rail_box_real_m.max().y()}) {
      for (double z : {setup_.rail_top_max_m - 0.02, setup_.rail_top_max_m + 0.03}) {
        const Eigen::Vector2f p = project_overview(Eigen::Vector3d(focus.x() + dx, y, z));
        bx0 = std::min(bx0, p.x());
        by0 = std::min(by0, p.y());
        bx1 = std::max(bx1, p.x());
        by1 = std::max(by1, p.y());
      }
    }
  }
  append_outline(list.overlay, bx0, by0, bx1, by1, line, palette::text);
  append_line(list.overlay, {bx1, by0}, {x0 - line, y0 - line}, line, palette::text);
  append_line(list.overlay, {bx1, by1}, {x0 - line, y1 + line}, line, palette::text);

  // Text fits the panel's width: 2x at 720p, 3x at 1080p, smaller in a narrow picture (not below 1x).
  const double k = setup_.exaggeration.factor;
  // A step joint: the straightedge runs from one rail top to the other, so
  // its dip is nil and the step is what a track engineer would read off it
  // (under a micrometre: a dipped joint's level ends).
  const double rise_m = setup_.straightedge.end_m.z() - setup_.straightedge.start_m.z();
  const double step_m = std::abs(rise_m) >= 1e-6 ? rise_m : 0.0;
  const std::string caption = format_label("contact region, heights x%g", k);
  const double t_ms = t_s * 1e3, x_mm = sample.centre_m.x() * 1e3, z_mm = sample.centre_m.z() * 1e3;
  const double spin_deg = sample.spin_angle_rad * 180.0 / std::numbers::pi, dip_mm = setup_.straightedge.dip_m * 1e3;
  // The legend in full, and short (the same values and key in fewer, narrower
  // lines) for a panel too small for the full one at 1x. The impact lines are
  // kept without an impact, so the rest does not move from frame to frame.
  std::string full = format_label("t = %.4f ms   wheel x = %+.3f mm\n", t_ms, x_mm);
  full += format_label("centre z = %.4f mm   spin = %.2f deg\n\n", z_mm, spin_deg);
  full += "left: the whole wheel, to scale\n";
  full += format_label("right: the contact, heights x%g\n", k);
  full += "dark bar: straightedge on the rail ends\n";
  full += format_label("  dip under it %.2f mm\n", dip_mm);
  if (step_m != 0.0) full += format_label("  outgoing rail %+.2f mm (a step)\n", step_m * 1e3);
  full += "magenta: contact points\n";
  full += "orange ring: impact point";
  const std::string full_impact = current != nullptr ? format_label("IMPACT at t = %.4f ms\ndp_z = %.2f N s\n\n",
                                                              current->time_s * 1e3, current->momentum_jump_Ns)
                                                     : std::string("\n\n\n");
  std::string short_text = format_label("t = %.4f ms   spin = %.2f deg\n", t_ms, spin_deg);
  short_text += format_label("wheel x = %+.3f mm\ncentre z = %.4f mm\n", x_mm, z_mm);
  short_text += format_label("left: to scale\nright: heights x%g\n", k);
  short_text += format_label("bar: straightedge, dip %.2f mm\n", dip_mm);
  if (step_m != 0.0) short_text += format_label("  step %+.2f mm\n", step_m * 1e3);
  short_text += "magenta: contacts\norange ring: impact point";
  const std::string short_impact = current != nullptr ? format_label("IMPACT at t = %.4f ms\ndp_z = %.2f N s\n",
                                                               current->time_s * 1e3, current->momentum_jump_Ns)
                                                      : std::string("\n\n");
  const float room_x = static_cast<float>(legend.width) - 8.0f * line;
  const float room_y = static_cast<float>(legend.height) - 8.0f * line;
  auto fit = [&](const std::string& all) {
    const Eigen::Vector2f unit = text_size_px(all, 1.0f);
    return std::min(room_x / unit.x(), room_y / unit.y());
  };
  const bool in_short = fit(full_impact + full) < 1.0f;
  const std::string& text = in_short ? short_text : full;
  const std::string& impact_text = in_short ? short_impact : full_impact;
  // Never below 1x: a stroke of stb_easy_font's narrower than a pixel misses
  // pixel centres and vanishes. A picture too small for the short legend at
  // 1x has it cut at the frame's edge, below the inset.
  const float scale = std::max(1.0f, std::min(setup_.text_scale(), fit(impact_text + text)));
  const float pad = 3.0f * scale;
  const Eigen::Vector2f caption_size = text_size_px(caption, scale);
  append_rectangle(list.overlay, x0, y0, x0 + caption_size.x() + 2.0f * pad, y0 + caption_size.y() + 2.0f * pad,
                   palette::background);
  append_text(list.overlay, caption, x0 + pad, y0 + pad, scale, palette::text);

  // Names on the overview, below the rails where the ground is, clear of the
  // wheel and of the contact; off the frame's edges and the impact frame's
  // border in every frame alike, so that no name jumps.
  const float edge = std::max(2.0f * pad, setup_.impact_border_px() + pad);
  auto name = [&](const std::string& label, const Eigen::Vector3d& anchor_m, bool above) {
    const Eigen::Vector2f p = project_overview(anchor_m);
    const Eigen::Vector2f size = text_size_px(label, scale);
    const float tx = std::clamp(p.x() - 0.5f * size.x(), edge,
                                static_cast<float>(overview_rect_.width) - size.x() - 2.0f * pad);
    const float ty = above ? std::max(p.y() - 14.0f * pad - size.y(), edge)
                           : std::min(p.y() + 10.0f * pad, static_cast<float>(overview_rect_.height) - size.y() - edge);
    append_line(list.overlay, p, {tx + 0.5f * size.x(), above ? ty + size.y() : ty}, line * 0.5f, palette::text);
    append_rectangle(list.overlay, tx - pad, ty - pad, tx + size.x() + pad, ty + size.y() + pad, palette::background);
    append_text(list.overlay, label, tx, ty, scale, palette::text);
  };
  const double bottom = setup_.rail_box_real_m.min().z(), near_y = setup_.rail_box_real_m.min().y();
  const double x_lo = std::max(setup_.rail_box_real_m.min().x(), focus.x() - 1.1 * setup_.wheel_radius_m);
  const double x_hi = std::min(setup_.rail_box_real_m.max().x(), focus.x() + 1.1 * setup_.wheel_radius_m);
  name("incoming rail", {x_lo + 0.15 * (x_hi - x_lo), near_y, bottom}, false);
  name("outgoing rail", {x_hi - 0.22 * (x_hi - x_lo), near_y, bottom}, false);
  name(format_label("straightedge: dip %.1f mm", setup_.straightedge.dip_m * 1e3) +
           (step_m != 0.0 ? format_label(", step %+.1f mm", step_m * 1e3) : std::string()),
       {x_lo + 0.06 * (x_hi - x_lo), near_y - 0.008, setup_.straightedge.start_m.z()}, true);

  // Names in the inset, on the rails' near side faces 1.5 mm (drawn 30 mm at
  // k = 20) below the wheel's lowest point, left and right of the contact,
  // kept inside the inset.
  auto inset_name = [&](const std::string& label, const Eigen::Vector3d& real_m) {
    const Eigen::Vector2f p = project_to_pixel(inset_camera, inset, setup_.exaggeration.point(real_m));
    const Eigen::Vector2f size = text_size_px(label, scale);
    const float tx = std::clamp(p.x() - 0.5f * size.x(), x0 + pad, x1 - size.x() - pad);
    const float ty = std::clamp(p.y(), y0 + caption_size.y() + 3.0f * pad, y1 - size.y() - pad);
    append_rectangle(list.overlay, tx - pad, ty - pad, tx + size.x() + pad, ty + size.y() + pad, palette::background);
    append_text(list.overlay, label, tx, ty, scale, palette::text);
  };
  const double face_y = setup_.rail_box_real_m.min().y(), face_z = sample.centre_m.z() - setup_.wheel_radius_m - 0.0015;
  inset_name("incoming rail", {focus.x() - 0.35 * half * 2.0, face_y, face_z});
  inset_name("outgoing rail", {focus.x() + 0.30 * half * 2.0, face_y, face_z});

  const float lx = static_cast<float>(legend.x) + 4.0f * line, ly = static_cast<float>(legend.y) + 4.0f * line;
  if (current != nullptr) {
    append_text(list.overlay, impact_text, lx, ly, scale, palette::impact);
    append_border(list.overlay, setup_.settings.width_px, setup_.settings.height_px, setup_.impact_border_px(), palette::impact);
  }
  append_text(list.overlay, text, lx, ly + text_size_px(impact_text, scale).y(), scale, palette::text);
}

}  // namespace railjoint
