#include "renders/close_view_labels.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renders/palette.h"
#include "renders/text_overlay.h"

namespace railjoint {

namespace {

// 1, 2 or 5 times a power of ten: the largest such length not above `at_most`.
double nice_length(double at_most) {
  const double decade = std::pow(10.0, std::floor(std::log10(at_most)));
  for (double m : {5.0, 2.0}) {
    if (m * decade <= at_most) return m * decade;
  }
  return decade;
}

std::string length_text(double length_m) {
  return length_m >= 1.0 ? format_label("%g m", length_m) : format_label("%g mm", length_m * 1e3);
}

}  // namespace

void append_close_view_labels(FrameDrawList& list, const CrossingSetup& setup, double t_s, const WheelSample& sample,
                              const Camera& camera, double px_per_m, const ImpactEvent* current,
                              const std::string& view_lines, bool vertical_bar) {
  const float w = static_cast<float>(setup.settings.width_px);
  const float h = static_cast<float>(setup.settings.height_px);
  // The block of labels sits at the bottom left, over the rails' interior in
  // the side view (the geometry of interest, the contact and a lift-off, lies
  // at and above the wheel's lowest point in the middle).
  const float scale = setup.text_scale();
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
  const double k = setup.exaggeration.factor;
  std::string label = format_label("t = %.4f ms   wheel x = %+.3f mm   z = %.4f mm   spin = %.2f deg", t_s * 1e3,
                                   sample.centre_m.x() * 1e3, sample.centre_m.z() * 1e3,
                                   sample.spin_angle_rad * 180.0 / std::numbers::pi);
  label += '\n';
  label += view_lines;
  const Box labels = boxed_text(label, margin + pad, h - margin - pad - text_size_px(label, scale).y(), palette::text);
  Box impact_box{0.0f, 0.0f, 0.0f, 0.0f};
  if (current != nullptr) {
    impact_box = boxed_text(
        format_label("IMPACT at t = %.4f ms: dp_z = %.2f N s", current->time_s * 1e3, current->momentum_jump_Ns),
        margin + pad, margin + pad, palette::impact);
    append_border(list.overlay, setup.settings.width_px, setup.settings.height_px, setup.impact_border_px(),
                  palette::impact);
  }

  // The bars meet at the lower right corner.
  if (camera.orthographic) {
    const double bar_x_m = nice_length(camera.visible_width_m / 6.0);
    const float bar_x_px = static_cast<float>(bar_x_m * px_per_m);
    const float thick = 2.0f * scale, gap = 3.0f * scale;
    const std::string x_text = length_text(bar_x_m);
    const Eigen::Vector2f x_size = text_size_px(x_text, scale);
    std::string z_text;
    float bar_z_px = 0.0f;
    Eigen::Vector2f z_size = Eigen::Vector2f::Zero();
    if (vertical_bar) {
      const double bar_z_m = nice_length(camera.visible_height_m / (4.0 * k));
      bar_z_px = static_cast<float>(bar_z_m * k * px_per_m);
      z_text = length_text(bar_z_m) + format_label(" (drawn x%g)", k);
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

}  // namespace railjoint
