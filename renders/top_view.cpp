#include "renders/top_view.h"

#include <algorithm>
#include <string>
#include <vector>

#include "models/contact_patch.h"
#include "renders/close_view_labels.h"
#include "renders/text_overlay.h"

namespace railjoint {

TopView::TopView(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
                 const Trajectory& trajectory)
    : CrossingView(settings, rails, wheel, trajectory) {
  const double view_width_m = visible_width_m(setup_.settings, setup_.framing);
  px_per_m_ = static_cast<double>(setup_.settings.width_px) / view_width_m;
  setup_.open_gl(rail_pair_vertices(rails.incoming, rails.outgoing), wheel, view_width_m, px_per_m_);
  ground_ = setup_.gl->add_triangles(setup_.checker_ground());
  band_ = setup_.gl->add_triangles({});
  cut_line_ = setup_.gl->add_triangles(cut_line_on_top(rails, 2.0 * (1.0 / px_per_m_)));  // 2 px wide
}

void TopView::show_contact_patch(const PressureInputs& inputs) {
  contact_patch_ = inputs;
  if (patch_ < 0) patch_ = setup_.gl->add_triangles({});
}

std::optional<PatchPlacement> TopView::contact_patch_at(double t_s) const {
  if (!contact_patch_) return std::nullopt;
  // The foremost touching contact: at the impact the wheel touches both rail
  // ends and its load goes over to the outgoing one.
  const Trajectory& trajectory = setup_.trajectory;
  const WheelSample sample = sample_at(trajectory, t_s);
  std::optional<double> contact_x_m;
  for (const ContactSample& contact : sample.contacts) {
    if (contact.distance_m > kTouchingGap_m) continue;
    contact_x_m = std::max(contact_x_m.value_or(contact.point_on_rail_m.x()), contact.point_on_rail_m.x());
  }
  // From the located impact instant to the end of the steps that carried it
  // the wheel touches the struck point, though the nearer recorded sample
  // (sample_at's contacts) may be the one before the impact.
  for (const ImpactEvent& impact : trajectory.impacts) {
    if (impact.last_sample >= trajectory.samples.size()) continue;
    if (t_s < impact.time_s || t_s > trajectory.samples[impact.last_sample].time_s) continue;
    contact_x_m = std::max(contact_x_m.value_or(impact.contact_point_m.x()), impact.contact_point_m.x());
  }
  if (!contact_x_m) return std::nullopt;  // in flight
  return place_contact_patch(*contact_patch_, {*contact_x_m, setup_.wheel_y_m}, setup_.rail_half_width_m);
}

void TopView::update_meshes(double t_s) {
  // The band just above the highest rail top: seen from above it lies on the rail head.
  const double y_lo = std::max(setup_.wheel_y_m - setup_.wheel_half_width_m, -setup_.rail_half_width_m);
  const double y_hi = std::min(setup_.wheel_y_m + setup_.wheel_half_width_m, setup_.rail_half_width_m);
  setup_.gl->update_triangles(band_, running_band(setup_.trajectory, t_s, y_lo, y_hi, setup_.rail_top_max_m + 1e-5));
  if (patch_ >= 0) {
    // Over the running band.
    const std::optional<PatchPlacement> placement = contact_patch_at(t_s);
    setup_.gl->update_triangles(
        patch_, placement ? contact_patch_vertices(*contact_patch_, *placement, setup_.rail_top_max_m + 2e-5)
                          : std::vector<MeshVertex>{});
  }
}

FrameDrawList TopView::frame_at(double t_s) const {
  const WheelSample sample = sample_at(setup_.trajectory, t_s);
  const Camera camera = camera_at(t_s);
  FrameDrawList list;
  SceneDraw scene = close_scene(camera, ground_);
  const Eigen::Matrix4f e = setup_.exaggeration.matrix().cast<float>();
  scene.meshes.push_back({band_, e});
  if (patch_ >= 0) scene.meshes.push_back({patch_, e});
  scene.meshes.push_back({cut_line_, e});
  // Seen from above the wheel lies over its own footprint: drawn
  // translucent, so the running band and the contacts show through it.
  MeshDraw body{setup_.wheel_mesh, e * wheel_pose(sample)};
  body.cull_back_faces = true;
  body.opacity = 0.35f;
  scene.meshes.push_back(body);
  append_contact_markers(scene, setup_, t_s, sample, setup_.close_marker_px(), true);
  list.scenes.push_back(scene);

  const double half = setup_.wheel_half_width_m;
  std::string lines = "top view: the wheel drawn see-through over its footprint\n";
  lines += "dark strip: rail head the wheel has touched, ";
  lines += format_label(half < 0.001 ? "a line %.1f mm wide\n" : "%.1f mm wide\n", 2e3 * half);
  lines += "magenta: contact points   orange ring: impact point";
  if (contact_patch_) {
    const ContactPatch& patch = contact_patch_->patch;
    lines += "\nteal: the local model's contact patch, " + std::string(to_string(patch.shape)) +
             format_label(" %.1f x %.1f mm; red: its part over the gap", patch.length_m * 1e3, patch.width_m * 1e3);
    const std::optional<PatchPlacement> placement = contact_patch_at(t_s);
    const double a0_m2 = patch_area_m2(patch);
    lines += placement ? format_label("\nA/A0 = %.3f   P = %.0f MPa (N = %.1f kN; P0 = %.0f MPa)",
                                      placement->state.active_area_m2 / a0_m2, placement->state.pressure_Pa * 1e-6,
                                      contact_patch_->normal_force_N * 1e-3,
                                      contact_patch_->normal_force_N / a0_m2 * 1e-6)
                       : std::string("\nno patch: the wheel is in flight");
  }
  append_close_view_labels(list, setup_, t_s, sample, camera, px_per_m_, setup_.impact_within_one_frame(t_s), lines,
                           false);
  return list;
}

}  // namespace railjoint
