// The top view of the patch crossing the gap (renders/patch_crossing_frames.h):
// frames are written, and the reduction area (red) appears only while the
// patch is over the gap: not in the first frame (x_front = 0, the patch
// touches the gap's corner only), clearly in the middle one.

#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>
#include <stb_image.h>

#include "renders/patch_crossing_frames.h"
#include "renders/render_crossing.h"
#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

// Pixels of the "over the gap" red (0.90, 0.20, 0.15): red high, green and blue low.
int red_pixels(const std::filesystem::path& png) {
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(png.string().c_str(), &w, &h, &channels, 3);
  if (data == nullptr) return -1;
  int count = 0;
  for (int i = 0; i < w * h; ++i) {
    const unsigned char* p = data + 3 * i;
    if (p[0] > 200 && p[1] < 90 && p[2] < 90) ++count;
  }
  stbi_image_free(data);
  return count;
}

TEST(PatchCrossingFrames, ReductionAreaShowsOnlyOverTheGap) {
  PressureInputs in;
  in.gap = EndPostGap{0.006, std::numbers::pi / 6.0};
  const std::filesystem::path dir = testing_support::scratch_path("patch_frames");
  const PatchCrossingFrames report = render_patch_crossing(in, dir, 5, 480, 270);
  EXPECT_EQ(report.frames_written, 5);
  const int first = red_pixels(dir / frame_file_name(0));
  const int middle = red_pixels(dir / frame_file_name(2));
  std::printf("red pixels: first frame %d, middle frame %d (draw %.2f ms a frame)\n", first, middle,
              report.draw_ms_per_frame);
  EXPECT_EQ(first, 0);
  // Middle frame: x_front = x_end / 2 = 19.4 mm, the patch centred near the
  // gap; R ~ 40 % of the 150.8 mm^2 patch at ~9.7 px/mm: some 600 px.
  EXPECT_GT(middle, 200);
}

}  // namespace
}  // namespace railjoint
