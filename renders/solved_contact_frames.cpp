#include "renders/solved_contact_frames.h"

#include <algorithm>
#include <cmath>

#include "models/rail_top.h"
#include "renders/png_file.h"
#include "renders/render_crossing.h"
#include "renders/video_assembly.h"

namespace railjoint {

namespace {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

// Black body: black -> red -> yellow -> white as s goes 0 -> 1 (monotone in
// lightness, so the peak reads as the brightest spot in grey print too).
Rgb heat(double s) {
  s = std::clamp(s, 0.0, 1.0);
  const auto channel = [](double v) { return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0))); };
  return {channel(3.0 * s), channel(3.0 * s - 1.0), channel(3.0 * s - 2.0)};
}

void put(RgbImage& image, int column, int row, Rgb c) {
  if (column < 0 || row < 0 || column >= image.width_px || row >= image.height_px) return;
  std::uint8_t* p = image.rgb.data() +
                    (static_cast<std::size_t>(row) * static_cast<std::size_t>(image.width_px) +
                     static_cast<std::size_t>(column)) * 3;
  p[0] = c.r;
  p[1] = c.g;
  p[2] = c.b;
}

}  // namespace

RgbImage solved_contact_frame(const JointParams& joint, const RailEndField& field, double scale_Pa,
                              double largest_load_N, int width_px, int height_px) {
  RgbImage image;
  image.width_px = width_px;
  image.height_px = height_px;
  image.rgb.assign(static_cast<std::size_t>(width_px) * static_cast<std::size_t>(height_px) * 3, 40);
  const RailEndGap& g = field.gap;
  const int nx = static_cast<int>(g.gap_m.rows());
  const int ny = static_cast<int>(g.gap_m.cols());
  if (nx == 0 || ny == 0) return image;  // a step in flight: no contact, no grid
  // The grid fills the picture above a 1/12 strip for the load bar; x to
  // the right (the direction of travel), y up, one scale for both axes.
  const int bar_px = std::max(6, height_px / 12);
  const double width_m = nx * g.dx_m;
  const double height_m = ny * g.dy_m;
  const double px_per_m = std::min(width_px / width_m, (height_px - bar_px) / height_m);
  const double left_px = 0.5 * (width_px - px_per_m * width_m);
  const double top_px = 0.5 * (height_px - bar_px - px_per_m * height_m);
  const double x_left = g.x0_m - 0.5 * g.dx_m;
  const double y_top = g.y0_m + (ny - 0.5) * g.dy_m;
  for (int row = 0; row < height_px - bar_px; ++row) {
    const double y = y_top - (row + 0.5 - top_px) / px_per_m;
    const int j = static_cast<int>(std::floor((y - (g.y0_m - 0.5 * g.dy_m)) / g.dy_m));
    if (j < 0 || j >= ny) continue;
    for (int column = 0; column < width_px; ++column) {
      const double x = x_left + (column + 0.5 - left_px) / px_per_m;
      const int i = static_cast<int>(std::floor((x - x_left) / g.dx_m));
      if (i < 0 || i >= nx) continue;
      put(image, column, row, g.no_surface(i, j) ? Rgb{128, 128, 128} : heat(field.pressure_Pa(i, j) / scale_Pa));
    }
  }
  // The cut faces (incoming end's and outgoing end's), one point a pixel row.
  for (int rail : {0, 1}) {
    for (int row = 0; row < height_px - bar_px; ++row) {
      const double y = y_top - (row + 0.5 - top_px) / px_per_m;
      if (y < g.y0_m - 0.5 * g.dy_m || y > y_top) continue;
      const double x_cut = cut_x_m(joint, y, rail);
      if (x_cut < x_left || x_cut > x_left + width_m) continue;  // the face beyond the grid
      const int column = static_cast<int>(std::lround(left_px + (x_cut - x_left) * px_per_m));
      for (int w = -1; w <= 1; ++w) put(image, column + w, row, Rgb{80, 160, 255});
    }
  }
  // The load bar: this step's N against the crossing's largest.
  const int bar_len = largest_load_N > 0.0
                          ? static_cast<int>(std::lround(width_px * field.step.normal_force_N / largest_load_N))
                          : 0;
  for (int row = height_px - bar_px + 2; row < height_px - 2; ++row) {
    for (int column = 0; column < bar_len; ++column) put(image, column, row, Rgb{80, 200, 120});
  }
  return image;
}

SolvedContactFrames write_solved_contact_frames(const JointParams& joint, const std::vector<RailEndField>& fields,
                                                const std::filesystem::path& out_dir, int width_px, int height_px) {
  double scale = 0.0;
  double largest = 0.0;
  for (const RailEndField& f : fields) {
    scale = std::max(scale, f.step.max_pressure_Pa);
    largest = std::max(largest, f.step.normal_force_N);
  }
  if (!(scale > 0.0)) scale = 1.0;  // every step in flight: black frames
  // 30 frames a second on screen, as the patch's frames (patch_crossing_frames.cpp).
  VideoPipe video(out_dir, width_px, height_px, 30.0);
  SolvedContactFrames report;
  for (const RailEndField& f : fields) {
    const RgbImage frame = solved_contact_frame(joint, f, scale, largest, width_px, height_px);
    video.write(frame);
    write_png(out_dir / frame_file_name(report.frames_written), frame);
    ++report.frames_written;
  }
  static_cast<VideoFiles&>(report) = video.finish();
  return report;
}

}  // namespace railjoint
