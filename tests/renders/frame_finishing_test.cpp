// The CPU's share of a frame, done after each frame is drawn (no GL
// needed): finish_frame (GL's bottom-first RGBA to RGB rows top first, FXAA,
// labels over it) and FXAA's invariants. Expected values are hand-made
// pictures and symmetries, not numbers taken from the code.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "renders/fxaa.h"
#include "renders/read_back_frame.h"

namespace railjoint {
namespace {

RgbImage blank(int w, int h, std::uint8_t grey) {
  RgbImage image;
  image.width_px = w;
  image.height_px = h;
  image.rgb.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3, grey);
  return image;
}

void set(RgbImage& image, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  std::uint8_t* p = image.rgb.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width_px) +
                                        static_cast<std::size_t>(x)) * 3;
  p[0] = r;
  p[1] = g;
  p[2] = b;
}

RgbImage mirrored_left_right(const RgbImage& image) {
  RgbImage out = image;
  for (int y = 0; y < image.height_px; ++y) {
    for (int x = 0; x < image.width_px; ++x) {
      const std::uint8_t* p = image.pixel(image.width_px - 1 - x, y);
      set(out, x, y, p[0], p[1], p[2]);
    }
  }
  return out;
}

RgbImage mirrored_top_bottom(const RgbImage& image) {
  RgbImage out = image;
  for (int y = 0; y < image.height_px; ++y) {
    for (int x = 0; x < image.width_px; ++x) {
      const std::uint8_t* p = image.pixel(x, image.height_px - 1 - y);
      set(out, x, y, p[0], p[1], p[2]);
    }
  }
  return out;
}

// A dark disc on a light ground: edges in every direction, as a wheel has.
RgbImage disc_picture(int w, int h) {
  RgbImage image = blank(w, h, 235);
  const double cx = 0.47 * w, cy = 0.53 * h, r = 0.31 * std::min(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) set(image, x, y, 40, 90, 200);
    }
  }
  return image;
}

// GL's read-back of `image` with every pixel's alpha 255: rows bottom first.
ReadBackFrame as_read_back(const RgbImage& image) {
  ReadBackFrame frame;
  frame.width_px = image.width_px;
  frame.height_px = image.height_px;
  for (int y = image.height_px - 1; y >= 0; --y) {
    for (int x = 0; x < image.width_px; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      frame.picture_rgba.insert(frame.picture_rgba.end(), {p[0], p[1], p[2], 255});
    }
  }
  return frame;
}

TEST(FinishFrame, TurnsGlRowsBottomFirstIntoRgbRowsTopFirst) {
  // 7 x 3 (7 is not a multiple of the four pixels converted a step): every
  // channel of every pixel distinct, so a swapped byte, row or column shows.
  RgbImage expected = blank(7, 3, 0);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 7; ++x) {
      const auto base = static_cast<std::uint8_t>(10 * (7 * y + x));
      set(expected, x, y, base, static_cast<std::uint8_t>(base + 1), static_cast<std::uint8_t>(base + 2));
    }
  }
  ReadBackFrame frame = as_read_back(expected);
  for (std::size_t i = 3; i < frame.picture_rgba.size(); i += 4) frame.picture_rgba[i] = 77;  // alpha is dropped
  RgbImage out;
  finish_frame(frame, out);
  EXPECT_EQ(out.width_px, 7);
  EXPECT_EQ(out.height_px, 3);
  EXPECT_EQ(out.rgb, expected.rgb);
}

TEST(FinishFrame, LabelsReplaceThePictureWhereTheyCoverItAfterSmoothing) {
  const RgbImage picture = disc_picture(40, 30);
  ReadBackFrame frame = as_read_back(picture);
  frame.fxaa = true;
  // A label pixel on the disc's edge (row 10 from the top), where FXAA
  // changes the picture, and one far from it (row 2), as GL hands labels
  // over: RGBA rows bottom first, alpha 255 where a label covers the pixel.
  int edge_x = 0;  // the disc's left edge on row 10
  while (picture.pixel(edge_x, 10)[2] != 200) ++edge_x;
  frame.labels_rgba.assign(frame.picture_rgba.size(), 0);
  auto label = [&](int x, int y, std::initializer_list<std::uint8_t> rgba) {
    std::copy(rgba.begin(), rgba.end(), frame.labels_rgba.begin() + ((29 - y) * 40 + x) * 4);
  };
  label(edge_x, 10, {255, 128, 0, 255});
  label(3, 2, {1, 2, 3, 255});
  label(20, 25, {9, 9, 9, 0});  // not covered: its colour must not show

  RgbImage out;
  finish_frame(frame, out);
  RgbImage smoothed = picture;
  apply_fxaa(smoothed);
  ASSERT_NE(std::vector<std::uint8_t>(smoothed.pixel(edge_x, 10), smoothed.pixel(edge_x, 10) + 3),
            std::vector<std::uint8_t>(picture.pixel(edge_x, 10), picture.pixel(edge_x, 10) + 3))
      << "the test needs a pixel FXAA changes under the label";
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 40; ++x) {
      const std::uint8_t* got = out.pixel(x, y);
      std::vector<std::uint8_t> want(smoothed.pixel(x, y), smoothed.pixel(x, y) + 3);
      if (x == edge_x && y == 10) want = {255, 128, 0};  // crisp: not smoothed, and not mixed with the picture
      if (x == 3 && y == 2) want = {1, 2, 3};
      ASSERT_EQ(std::vector<std::uint8_t>(got, got + 3), want) << "pixel (" << x << ", " << y << ")";
    }
  }
}

TEST(FinishFrame, RefusesBuffersThatDoNotMatchTheSize) {
  ReadBackFrame frame = as_read_back(blank(4, 4, 9));
  frame.width_px = 5;
  RgbImage out;
  EXPECT_THROW(finish_frame(frame, out), std::invalid_argument);
  frame.width_px = 4;
  frame.labels_rgba.resize(4 * 4 * 4 - 1);  // labels of another size than the picture
  EXPECT_THROW(finish_frame(frame, out), std::invalid_argument);
}

TEST(Fxaa, LeavesAFlatPictureAndPixelsAwayFromEdgesAlone) {
  RgbImage flat = blank(33, 17, 123);
  const RgbImage before = flat;
  apply_fxaa(flat);
  EXPECT_EQ(flat.rgb, before.rgb);

  // A vertical edge between columns 15 and 16: only those two columns may change.
  RgbImage edge = blank(32, 16, 230);
  for (int y = 0; y < 16; ++y) {
    for (int x = 16; x < 32; ++x) set(edge, x, y, 30, 60, 90);
  }
  const RgbImage unsmoothed = edge;
  apply_fxaa(edge);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 32; ++x) {
      if (x == 15 || x == 16) continue;
      for (int k = 0; k < 3; ++k) EXPECT_EQ(edge.pixel(x, y)[k], unsmoothed.pixel(x, y)[k]) << x << ", " << y;
    }
  }
}

TEST(Fxaa, BlendsOnlyBetweenTheColoursAtTheEdgeAndSmoothsAStaircase) {
  RgbImage image = disc_picture(64, 48);
  const RgbImage before = image;
  apply_fxaa(image);
  int changed = 0;
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      const bool border = x == 0 || y == 0 || x == 63 || y == 47;
      for (int k = 0; k < 3; ++k) {
        const int ground = 235, disc = k == 0 ? 40 : k == 1 ? 90 : 200;
        const int v = image.pixel(x, y)[k];
        EXPECT_GE(v, std::min(ground, disc));
        EXPECT_LE(v, std::max(ground, disc));
        if (border) {
          EXPECT_EQ(v, before.pixel(x, y)[k]) << "the outermost rows and columns stay";
        }
      }
      if (image.pixel(x, y)[1] != before.pixel(x, y)[1]) {
        const int g = image.pixel(x, y)[1];
        if (g != 90 && g != 235) ++changed;  // a shade between the two: smoothed
      }
    }
  }
  // The disc's staircase outline is about 2 pi r = 93 pixels long; FXAA
  // gives most pixels along it an in-between shade.
  EXPECT_GT(changed, 40);
}

TEST(Fxaa, CommutesWithMirroringExactly) {
  // The filter has no preferred side: its taps lie symmetrically about the
  // pixel and are rounded the same way either side of it, so mirroring
  // before or after gives the same bytes.
  const RgbImage picture = disc_picture(61, 45);
  RgbImage smoothed = picture;
  apply_fxaa(smoothed);
  RgbImage lr = mirrored_left_right(picture);
  apply_fxaa(lr);
  EXPECT_EQ(lr.rgb, mirrored_left_right(smoothed).rgb);
  RgbImage tb = mirrored_top_bottom(picture);
  apply_fxaa(tb);
  EXPECT_EQ(tb.rgb, mirrored_top_bottom(smoothed).rgb);
}

}  // namespace
}  // namespace railjoint
