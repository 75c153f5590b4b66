#include "renders/patch_crossing_frames.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

#include "models/patch_gap_overlap.h"
#include "renders/offscreen_renderer.h"
#include "renders/palette.h"
#include "renders/png_file.h"
#include "renders/render_crossing.h"
#include "renders/text_overlay.h"
#include "renders/video_assembly.h"

namespace railjoint {

namespace {

using Polygon = std::vector<Eigen::Vector2d>;

const Eigen::Vector3f kEndPost{0.25f, 0.25f, 0.28f};
const Eigen::Vector3f kBar{0.85f, 0.55f, 0.10f};

// World (metres, y up) to pixels (origin top-left, y down), square pixels.
struct PixelMap {
  double x0_m, y_mid_m, px_per_m, height_px;
  Eigen::Vector2f operator()(const Eigen::Vector2d& p) const {
    return {static_cast<float>((p.x() - x0_m) * px_per_m),
            static_cast<float>(height_px / 2.0 - (p.y() - y_mid_m) * px_per_m)};
  }
};

// A convex polygon as a triangle fan.
void fill_convex(std::vector<OverlayVertex>& out, const Polygon& polygon, const PixelMap& map, const Eigen::Vector3f& colour) {
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    for (const Eigen::Vector2d& p : {polygon[0], polygon[i], polygon[i + 1]}) out.push_back({map(p), colour});
  }
}

}  // namespace

PatchCrossingFrames render_patch_crossing(const PressureInputs& in, const std::filesystem::path& out_dir, int frame_count,
                                          int width_px, int height_px) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw std::runtime_error("cannot create " + out_dir.string() + ": " + ec.message());
  // Flat 2-D triangles on pixel-aligned rectangles: no anti-aliasing needed.
  OffscreenRenderer renderer(width_px, height_px, Antialiasing::none);  // throws when rendering is unavailable

  const std::vector<PressureState> traversal = pressure_traversal(in);
  const PressureSummary summary = summarize_pressure(in, traversal);
  const double a = in.patch.length_m;
  const double b = in.patch.width_m;
  const double x_end = summary.x_end_m;
  const double cot = std::cos(in.gap.theta_rad) / std::sin(in.gap.theta_rad);
  const double g_long = summary.g_long_m;

  // Visible: the patch's whole travel with a margin, the rail head drawn wider than the patch.
  const double x0 = -a - 0.15 * (x_end + a);
  const double x1 = x_end + 0.15 * (x_end + a);
  const double top_band_px = 0.22 * height_px;  // text and bar above the picture
  // Image row of y: top_band + (picture height)/2 - (y - b/2) s, i.e. a map whose 'height' is height + top_band.
  const PixelMap map{x0, b / 2.0, width_px / (x1 - x0), height_px + top_band_px};
  const double half_height_m = (height_px - top_band_px) / 2.0 / map.px_per_m;
  const double y0 = b / 2.0 - half_height_m;
  const double y1 = b / 2.0 + half_height_m;
  const Polygon incoming = {{x0, y0}, {y0 * cot, y0}, {y1 * cot, y1}, {x0, y1}};
  const Polygon end_post = {{y0 * cot, y0}, {y0 * cot + g_long, y0}, {y1 * cot + g_long, y1}, {y1 * cot, y1}};
  const Polygon outgoing = {{y0 * cot + g_long, y0}, {x1, y0}, {x1, y1}, {y1 * cot + g_long, y1}};
  const float scale = std::max(1.0f, static_cast<float>(height_px) / 270.0f);

  // 30 frames a second on screen, whatever the crossing's real duration.
  VideoPipe video(out_dir, width_px, height_px, 30.0);
  RgbImage image;
  double draw_ms = 0.0;
  for (int k = 0; k < frame_count; ++k) {
    const double x_front = x_end * k / (frame_count - 1);
    const PressureState state = pressure_state(in, x_front);
    FrameDrawList frame;
    frame.background = palette::background;
    // The picture's band: rails, end post, patch, reduction area, in painting order.
    fill_convex(frame.overlay, incoming, map, palette::rail_top);
    fill_convex(frame.overlay, outgoing, map, palette::rail_top * palette::outgoing_rail_shade);
    fill_convex(frame.overlay, end_post, map, kEndPost);
    const Polygon outline = patch_outline_m(in.patch, x_front);
    fill_convex(frame.overlay, outline, map, palette::patch_bearing);
    for (const Polygon& piece : outline_over_gap_m(outline, in.gap, b)) fill_convex(frame.overlay, piece, map, palette::patch_over_gap);

    const double relative = state.pressure_Pa / summary.p0_Pa;
    append_text(frame.overlay,
                format_label("theta = %.1f deg   g = %.1f mm   x_front = %.2f mm", in.gap.theta_rad * 180.0 / std::numbers::pi,
                     in.gap.gap_m * 1e3, x_front * 1e3) +
                    format_label("   t = %.4f ms", x_front / in.speed_m_per_s * 1e3),
                8.0f * scale, 6.0f * scale, scale, palette::text);
    append_text(frame.overlay,
                format_label("P = %.0f MPa   P/P0 = %.3f   dP/dt = %+.3e MPa/s", state.pressure_Pa * 1e-6, relative,
                     state.rate_Pa_per_m * in.speed_m_per_s * 1e-6),
                8.0f * scale, 20.0f * scale, scale, palette::text);
    // A bar from P0 to the crossing's highest pressure.
    const double fraction = (relative - 1.0) / std::max(1e-12, summary.max_relative_pressure() - 1.0);
    const float bar_x0 = 8.0f * scale;
    const float bar_x1 = static_cast<float>(width_px) - 8.0f * scale;
    append_rectangle(frame.overlay, bar_x0, 34.0f * scale, bar_x1, 40.0f * scale, palette::datum);
    append_rectangle(frame.overlay, bar_x0, 34.0f * scale, bar_x0 + static_cast<float>(fraction) * (bar_x1 - bar_x0),
                     40.0f * scale, kBar);
    append_text(frame.overlay, "teal: bearing on the rail ends   red: over the gap (reduction area)", 8.0f * scale,
                44.0f * scale, scale, palette::text);

    const auto start = std::chrono::steady_clock::now();
    renderer.draw(frame, image);
    draw_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    video.write(image);
    write_png(out_dir / frame_file_name(k), image);
  }

  PatchCrossingFrames report;
  report.frames_written = frame_count;
  report.draw_ms_per_frame = draw_ms / frame_count;
  static_cast<VideoFiles&>(report) = video.finish();
  return report;
}

}  // namespace railjoint
