#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "models/contact_patch.h"
#include "renders/crossing_renderer.h"
#include "renders/palette.h"
#include "renders/text_overlay.h"

// The overlay of each view: labels, the impact border, scale bars, legends.

namespace railjoint {

namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), pattern, a, b, c, d);
  return buffer;
}

// 1, 2 or 5 times a power of ten: the largest such length not above `at_most`.
double nice_length(double at_most) {
  const double decade = std::pow(10.0, std::floor(std::log10(at_most)));
  for (double m : {5.0, 2.0}) {
    if (m * decade <= at_most) return m * decade;
  }
  return decade;
}

std::string length_text(double length_m) {
  return length_m >= 1.0 ? format("%g m", length_m) : format("%g mm", length_m * 1e3);
}

}  // namespace

Eigen::Vector2f CrossingRenderer::project(const Camera& camera, const PixelRect& rect, const Eigen::Vector3d& point_m) {
  const Eigen::Vector4d clip = camera.projection * camera.view * point_m.homogeneous();
  const double u = 0.5 * (clip.x() / clip.w() + 1.0), v = 0.5 * (1.0 - clip.y() / clip.w());
  return {static_cast<float>(rect.x + u * rect.width), static_cast<float>(rect.y + v * rect.height)};
}

Eigen::Vector2f CrossingRenderer::project_overview(const Eigen::Vector3d& point_m) const {
  return project(overview_camera_, overview_rect_, point_m);
}

float CrossingRenderer::text_scale() const {
  // stb_easy_font's glyphs are about 7 px tall: 2x at 720p, 3x at 1080p.
  return std::max(1.0f, std::round(static_cast<float>(settings_.height_px) / 360.0f));
}

float CrossingRenderer::impact_border_px() const {
  return std::max(4.0f, static_cast<float>(settings_.height_px) / 90.0f);
}

void CrossingRenderer::append_close_view_labels(FrameDrawList& list, double t_s, const WheelSample& sample,
                                                const Camera& camera, const ImpactEvent* current) const {
  const float w = static_cast<float>(settings_.width_px);
  const float h = static_cast<float>(settings_.height_px);
  // Labels on opaque boxes. The block of labels sits at the bottom left, over
  // the rails' interior in the side view (the geometry of interest, the
  // contact and a lift-off, lies at and above the wheel's lowest point in the
  // middle); the impact line at the top left; the scale bars at the bottom right.
  const float scale = text_scale();
  const float margin = 6.0f * scale, pad = 3.0f * scale;
  struct Box {
    float x0, y0, x1, y1;
    bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  };
  auto boxed_text = [&](const std::string& text, float x, float y, const Eigen::Vector3f& colour) {
    const Eigen::Vector2f size = text_size_px(text, scale);
    const Box box{x - pad, y - pad, x + size.x() + pad, y + size.y() + pad};
    append_rectangle(list.overlay, box.x0, box.y0, box.x1, box.y1, palette::background);
    append_text(list.overlay, text, x, y, scale, colour);
    return box;
  };
  const double k = exaggeration_.factor;
  std::string label = format("t = %.4f ms   wheel x = %+.3f mm   z = %.4f mm   spin = %.2f deg", t_s * 1e3,
                             sample.centre_m.x() * 1e3, sample.centre_m.z() * 1e3,
                             sample.spin_angle_rad * 180.0 / std::numbers::pi);
  label += '\n';
  if (settings_.view == RenderView::side) {
    const double y = trajectory_.samples.front().centre_m.y();
    label += format("side view, rails cut to the wheel's width (y = %.2f .. %.2f mm)\n",
                    (y - wheel_half_width_m_) * 1e3, (y + wheel_half_width_m_) * 1e3);
    label += format("heights x%g about z = %g mm, the wheel too (drawn as an ellipse)\n", k,
                    settings_.reference_z_m * 1e3);
    label += "magenta: contact points   orange ring: impact point\n";
    label += format("green: path of the wheel's lowest point   grey line: z = %g mm", settings_.reference_z_m * 1e3);
  } else {
    label += "top view: the wheel drawn see-through over its footprint\n";
    label += "dark strip: rail head the wheel has touched, ";
    label += format(wheel_half_width_m_ < 0.001 ? "a line %.1f mm wide\n" : "%.1f mm wide\n", 2e3 * wheel_half_width_m_);
    label += "magenta: contact points   orange ring: impact point";
    if (contact_patch_) {
      const ContactPatch& patch = contact_patch_->patch;
      label += "\nteal: the local model's contact patch, " + std::string(to_string(patch.shape)) +
               format(" %.1f x %.1f mm; red: its part over the gap", patch.length_m * 1e3, patch.width_m * 1e3);
      const std::optional<PatchPlacement> placement = contact_patch_at(t_s);
      const double a0_m2 = patch_area_m2(patch);
      label += placement ? format("\nA/A0 = %.3f   P = %.0f MPa (N = %.1f kN; P0 = %.0f MPa)",
                                  placement->state.active_area_m2 / a0_m2, placement->state.pressure_Pa * 1e-6,
                                  contact_patch_->normal_force_N * 1e-3, contact_patch_->normal_force_N / a0_m2 * 1e-6)
                         : std::string("\nno patch: the wheel is in flight");
    }
  }
  const Box labels = boxed_text(label, margin + pad, h - margin - pad - text_size_px(label, scale).y(), palette::text);
  Box impact_box{0.0f, 0.0f, 0.0f, 0.0f};
  if (current != nullptr) {
    impact_box =
        boxed_text(format("IMPACT at t = %.4f ms: dp_z = %.2f N s", current->time_s * 1e3, current->momentum_jump_Ns),
                   margin + pad, margin + pad, palette::impact);
    append_border(list.overlay, settings_.width_px, settings_.height_px, impact_border_px(), palette::impact);
  }

  // Scale bars (orthographic views): a horizontal one in true length and, in
  // the side view, a vertical one in true length drawn k-fold, meeting at
  // the lower right corner. Bottom right, else top right, else none.
  if (camera.orthographic) {
    const double bar_x_m = nice_length(camera.visible_width_m / 6.0);
    const float bar_x_px = static_cast<float>(bar_x_m * px_per_m_);
    const float thick = 2.0f * scale, gap = 3.0f * scale;
    const std::string x_text = length_text(bar_x_m);
    const Eigen::Vector2f x_size = text_size_px(x_text, scale);
    std::string z_text;
    float bar_z_px = 0.0f;
    Eigen::Vector2f z_size = Eigen::Vector2f::Zero();
    if (settings_.view == RenderView::side) {
      const double bar_z_m = nice_length(camera.visible_height_m / (4.0 * k));
      bar_z_px = static_cast<float>(bar_z_m * k * px_per_m_);
      z_text = length_text(bar_z_m) + format(" (drawn x%g)", k);
      z_size = text_size_px(z_text, scale);
    }
    // Layout relative to the corner (cx, cy) where the bars meet: the
    // horizontal bar runs left from it, its length below; the vertical bar up.
    const float content_w = std::max({bar_x_px, x_size.x(), thick + gap + z_size.x()});
    const float content_h = std::max(bar_z_px, z_size.y()) + thick + gap + x_size.y();
    Box box{w - margin - content_w - 2.0f * pad, h - margin - content_h - 2.0f * pad, w - margin, h - margin};
    if (box.overlaps(labels)) {
      const float shift = margin - box.y0;
      box.y0 += shift;
      box.y1 += shift;
    }
    const bool fits = box.x0 >= 0.0f && box.y1 <= h && !box.overlaps(labels) &&
                      (current == nullptr || !box.overlaps(impact_box));
    if (fits) {
      const float cx = box.x1 - pad, cy = box.y1 - pad - x_size.y() - gap - thick;
      append_rectangle(list.overlay, box.x0, box.y0, box.x1, box.y1, palette::background);
      append_rectangle(list.overlay, cx - bar_x_px, cy, cx, cy + thick, palette::text);
      append_text(list.overlay, x_text, cx - x_size.x(), cy + thick + gap, scale, palette::text);
      if (bar_z_px > 0.0f) {
        append_rectangle(list.overlay, cx - thick, cy - bar_z_px, cx, cy + thick, palette::text);
        append_text(list.overlay, z_text, cx - thick - gap - z_size.x(), cy - bar_z_px, scale, palette::text);
      }
    }
  }
}

void CrossingRenderer::append_perspective_labels(FrameDrawList& list, double t_s, const WheelSample& sample,
                                                 const ImpactEvent* current) const {
  const float h = static_cast<float>(settings_.height_px);
  const PixelRect& inset = inset_rect_;
  const PixelRect& legend = legend_rect_;
  const float line = std::max(1.0f, h / 360.0f);  // 2 px at 720p

  // The panel right of the overview, round the inset and behind the legend:
  // four rectangles, laid first so that everything else lies on it.
  const float x0 = static_cast<float>(inset.x), y0 = static_cast<float>(inset.y);
  const float x1 = x0 + static_cast<float>(inset.width), y1 = y0 + static_cast<float>(inset.height);
  const float panel_x0 = static_cast<float>(overview_rect_.x + overview_rect_.width);
  const float w = static_cast<float>(settings_.width_px);
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
    for (double y : {rail_box_real_.min().y(), rail_box_real_.max().y()}) {
      for (double z : {rail_top_max_m_ - 0.02, rail_top_max_m_ + 0.03}) {
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
  const double k = exaggeration_.factor;
  // A step joint: the straightedge runs from one rail top to the other, so
  // its dip is nil and the step is what a track engineer would read off it
  // (under a micrometre: a dipped joint's level ends).
  const double rise_m = straightedge_.end_m.z() - straightedge_.start_m.z();
  const double step_m = std::abs(rise_m) >= 1e-6 ? rise_m : 0.0;
  const std::string caption = format("contact region, heights x%g", k);
  const double t_ms = t_s * 1e3, x_mm = sample.centre_m.x() * 1e3, z_mm = sample.centre_m.z() * 1e3;
  const double spin_deg = sample.spin_angle_rad * 180.0 / std::numbers::pi, dip_mm = straightedge_.dip_m * 1e3;
  // The legend in full, and short: the same values and key in fewer and
  // narrower lines, for a panel too small for the full one at 1x (a
  // 640 x 360 frame: the full legend ran off its right and bottom edges).
  // The impact lines are kept whether or not there is an impact, so the
  // rest does not move from frame to frame.
  std::string full = format("t = %.4f ms   wheel x = %+.3f mm\n", t_ms, x_mm);
  full += format("centre z = %.4f mm   spin = %.2f deg\n\n", z_mm, spin_deg);
  full += "left: the whole wheel, to scale\n";
  full += format("right: the contact, heights x%g\n", k);
  full += "dark bar: straightedge on the rail ends\n";
  full += format("  dip under it %.2f mm\n", dip_mm);
  if (step_m != 0.0) full += format("  outgoing rail %+.2f mm (a step)\n", step_m * 1e3);
  full += "magenta: contact points\n";
  full += "orange ring: impact point";
  const std::string full_impact = current != nullptr ? format("IMPACT at t = %.4f ms\ndp_z = %.2f N s\n\n",
                                                              current->time_s * 1e3, current->momentum_jump_Ns)
                                                     : std::string("\n\n\n");
  std::string short_text = format("t = %.4f ms   spin = %.2f deg\n", t_ms, spin_deg);
  short_text += format("wheel x = %+.3f mm\ncentre z = %.4f mm\n", x_mm, z_mm);
  short_text += format("left: to scale\nright: heights x%g\n", k);
  short_text += format("bar: straightedge, dip %.2f mm\n", dip_mm);
  if (step_m != 0.0) short_text += format("  step %+.2f mm\n", step_m * 1e3);
  short_text += "magenta: contacts\norange ring: impact point";
  const std::string short_impact = current != nullptr ? format("IMPACT at t = %.4f ms\ndp_z = %.2f N s\n",
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
  // pixel centres and vanishes (at 0.93x in a 640 x 360 frame "IMPACT" read
  // "IMPFCT"), so a picture too small for even the short legend at 1x (16:9
  // below about 560 x 315) has it cut at the frame's edge (below the inset:
  // the contact stays clear).
  const float scale = std::max(1.0f, std::min(text_scale(), fit(impact_text + text)));
  const float pad = 3.0f * scale;
  const Eigen::Vector2f caption_size = text_size_px(caption, scale);
  append_rectangle(list.overlay, x0, y0, x0 + caption_size.x() + 2.0f * pad, y0 + caption_size.y() + 2.0f * pad,
                   palette::background);
  append_text(list.overlay, caption, x0 + pad, y0 + pad, scale, palette::text);

  // Names on the overview, below the rails where the ground is, clear of
  // the wheel and of the contact.
  // Kept off the frame's edges, and off the impact frame's border (a portrait
  // frame's border is wider than the margin: it covered the start of the
  // straightedge's name), in every frame alike so that no name jumps.
  const float edge = std::max(2.0f * pad, impact_border_px() + pad);
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
  const double bottom = rail_box_real_.min().z(), near_y = rail_box_real_.min().y();
  const double x_lo = std::max(rail_box_real_.min().x(), focus.x() - 1.1 * wheel_radius_m_);
  const double x_hi = std::min(rail_box_real_.max().x(), focus.x() + 1.1 * wheel_radius_m_);
  name("incoming rail", {x_lo + 0.15 * (x_hi - x_lo), near_y, bottom}, false);
  name("outgoing rail", {x_hi - 0.22 * (x_hi - x_lo), near_y, bottom}, false);
  name(format("straightedge: dip %.1f mm", straightedge_.dip_m * 1e3) +
           (step_m != 0.0 ? format(", step %+.1f mm", step_m * 1e3) : std::string()),
       {x_lo + 0.06 * (x_hi - x_lo), near_y - 0.008, straightedge_.start_m.z()}, true);

  // Names in the inset, on the rails' near side faces 1.5 mm (drawn 30 mm at
  // k = 20) below the wheel's lowest point, left and right of the contact,
  // kept inside the inset.
  auto inset_name = [&](const std::string& label, const Eigen::Vector3d& real_m) {
    const Eigen::Vector2f p = project(inset_camera, inset, exaggeration_.point(real_m));
    const Eigen::Vector2f size = text_size_px(label, scale);
    const float tx = std::clamp(p.x() - 0.5f * size.x(), x0 + pad, x1 - size.x() - pad);
    const float ty = std::clamp(p.y(), y0 + caption_size.y() + 3.0f * pad, y1 - size.y() - pad);
    append_rectangle(list.overlay, tx - pad, ty - pad, tx + size.x() + pad, ty + size.y() + pad, palette::background);
    append_text(list.overlay, label, tx, ty, scale, palette::text);
  };
  const double face_y = rail_box_real_.min().y(), face_z = sample.centre_m.z() - wheel_radius_m_ - 0.0015;
  inset_name("incoming rail", {focus.x() - 0.35 * half * 2.0, face_y, face_z});
  inset_name("outgoing rail", {focus.x() + 0.30 * half * 2.0, face_y, face_z});

  const float lx = static_cast<float>(legend.x) + 4.0f * line, ly = static_cast<float>(legend.y) + 4.0f * line;
  if (current != nullptr) {
    append_text(list.overlay, impact_text, lx, ly, scale, palette::impact);
    append_border(list.overlay, settings_.width_px, settings_.height_px, impact_border_px(), palette::impact);
  }
  append_text(list.overlay, text, lx, ly + text_size_px(impact_text, scale).y(), scale, palette::text);
}

}  // namespace railjoint
