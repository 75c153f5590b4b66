// The CPU's share of a frame, done after each frame is drawn (no GL
// needed): finish_frame (GL's bottom-first RGBA to RGB rows top first, FXAA,
// labels over it), FXAA's invariants, and FrameFinisher's frame order and
// failures. Expected values are hand-made pictures and symmetries, not
// numbers taken from the code.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>
#include <stb_image.h>

#include "renders/frame_finisher.h"
#include "renders/fxaa.h"
#include "renders/label_raster.h"
#include "renders/read_back_frame.h"
#include "renders/render_crossing.h"
#include "renders/text_overlay.h"
#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

using testing_support::scratch_path;

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
  // A one-pixel label square on the disc's edge (row 10 from the top), one
  // far from it (row 2): pixel (x, y) is the square [x, x + 1] x [y, y + 1].
  int edge_x = 0;  // the disc's left edge on row 10
  while (picture.pixel(edge_x, 10)[2] != 200) ++edge_x;
  const float ex = static_cast<float>(edge_x);
  append_rectangle(frame.labels, ex, 10.0f, ex + 1.0f, 11.0f, {1.0f, 128.0f / 255.0f, 0.0f});
  append_rectangle(frame.labels, 3.0f, 2.0f, 4.0f, 3.0f, {1.0f / 255.0f, 2.0f / 255.0f, 3.0f / 255.0f});

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

// Which pixels a label covers: those whose centres lie in it; a centre on a
// side is in on the left and bottom sides, out on the right and top ones (y
// down; llvmpipe's rule, label_raster_gl_test checks it against GL), so
// abutting boxes share no pixel and leave none out.
TEST(LayLabels, ARectangleCoversThePixelsWhoseCentresItHolds) {
  RgbImage image = blank(12, 8, 0);
  std::vector<OverlayVertex> labels;
  // x from 2.5 to 6.5: centres 2.5 (left side: in) .. 5.5; 6.5 (right side): out.
  // y from 1.5 to 3.5: centre 1.5 (top side): out; 2.5; 3.5 (bottom side): in.
  append_rectangle(labels, 2.5f, 1.5f, 6.5f, 3.5f, {1.0f, 1.0f, 1.0f});
  // Abutting on the right: x from 6.5, its left side holds the centre 6.5.
  append_rectangle(labels, 6.5f, 1.5f, 8.0f, 3.5f, {0.0f, 0.0f, 1.0f});
  // Abutting below, green: y from 3.5 to 4.5; the centre 3.5 on its top
  // side stays the white box's, 4.5 on its bottom side is its own.
  append_rectangle(labels, 2.5f, 3.5f, 6.5f, 4.5f, {0.0f, 1.0f, 0.0f});
  lay_labels(labels, image);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 12; ++x) {
      const bool white = y >= 2 && y <= 3 && x >= 2 && x <= 5, blue = y >= 2 && y <= 3 && x >= 6 && x <= 7;
      const bool green = y == 4 && x >= 2 && x <= 5;
      const std::vector<std::uint8_t> want = white ? std::vector<std::uint8_t>{255, 255, 255}
                                             : blue ? std::vector<std::uint8_t>{0, 0, 255}
                                             : green ? std::vector<std::uint8_t>{0, 255, 0}
                                                     : std::vector<std::uint8_t>{0, 0, 0};
      EXPECT_EQ(std::vector<std::uint8_t>(image.pixel(x, y), image.pixel(x, y) + 3), want) << x << ", " << y;
    }
  }
}

// A slanted line (append_line: a rotated quad, drawn as two triangles): the
// pixels whose centres lie within half its thickness of the segment.
TEST(LayLabels, ASlantedLineCoversThePixelsWithinHalfItsThickness) {
  RgbImage image = blank(40, 40, 0);
  std::vector<OverlayVertex> labels;
  const Eigen::Vector2f a(3.0f, 5.0f), b(35.0f, 29.0f);  // a 3-4-5 slope
  append_line(labels, a, b, 3.0f, {1.0f, 1.0f, 1.0f});
  lay_labels(labels, image);
  const Eigen::Vector2f along = (b - a).normalized();
  int checked = 0;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x) {
      const Eigen::Vector2f c(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      const float t = (c - a).dot(along), d = std::abs((c - a).x() * along.y() - (c - a).y() * along.x());
      const bool inside = t >= 0.0f && t <= (b - a).norm() && d <= 1.5f;
      const bool clearly = inside ? (t > 0.01f && t < (b - a).norm() - 0.01f && d < 1.49f)
                                  : (t < -0.01f || t > (b - a).norm() + 0.01f || d > 1.51f);
      if (!clearly) continue;  // a centre on the outline: GL's tie rule decides
      ++checked;
      EXPECT_EQ(image.pixel(x, y)[0], inside ? 255 : 0) << x << ", " << y;
    }
  }
  EXPECT_GT(checked, 1500);
}

// Triangles that tile a square cover each pixel of it once, however many of
// their shared edges run through pixel centres: the square from (2.5, 2.5) to
// (18.5, 14.5) cut into eight triangles round (10.5, 8.5) through its corners
// and the midpoints of its sides, every corner on a pixel centre, so each
// shared edge (slopes 0, 3/4, 1 and infinite) meets centres exactly. By the
// rectangle rule above the square covers columns 2-17 (the centre on its left
// side in, on its right side out) and rows 3-14 (top side out, bottom side in).
TEST(LayLabels, TrianglesThatTileASquareCoverEachOfItsPixelsOnce) {
  const Eigen::Vector2f centre(10.5f, 8.5f);
  const std::vector<Eigen::Vector2f> rim = {{2.5f, 2.5f},   {10.5f, 2.5f},  {18.5f, 2.5f}, {18.5f, 8.5f},
                                            {18.5f, 14.5f}, {10.5f, 14.5f}, {2.5f, 14.5f}, {2.5f, 8.5f}};
  std::vector<int> count(24 * 20, 0);
  for (std::size_t k = 0; k < rim.size(); ++k) {
    RgbImage one = blank(24, 20, 0);
    // Half of them wound one way, half the other: the rule must not depend on it.
    const Eigen::Vector2f a = rim[k], b = rim[(k + 1) % rim.size()];
    std::vector<OverlayVertex> triangle = {{centre, {1.0f, 1.0f, 1.0f}}, {a, {1.0f, 1.0f, 1.0f}}, {b, {1.0f, 1.0f, 1.0f}}};
    if (k % 2 == 1) std::swap(triangle[1], triangle[2]);
    lay_labels(triangle, one);
    for (int y = 0; y < 20; ++y) {
      for (int x = 0; x < 24; ++x) count[static_cast<std::size_t>(y * 24 + x)] += one.pixel(x, y)[0] == 255 ? 1 : 0;
    }
  }
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 24; ++x) {
      const int want = x >= 2 && x <= 17 && y >= 3 && y <= 14 ? 1 : 0;
      EXPECT_EQ(count[static_cast<std::size_t>(y * 24 + x)], want) << "pixel (" << x << ", " << y << ")";
    }
  }
}

// A triangle with a corner that is not a number, or far beyond any frame, is
// left out (GL would clip it; the views never make one): nothing is drawn,
// nothing read or written out of bounds.
TEST(LayLabels, LeavesOutTrianglesWithCornersThatAreNotFiniteOrFarOut) {
  RgbImage image = blank(16, 16, 7);
  const Eigen::Vector3f white(1.0f, 1.0f, 1.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  std::vector<OverlayVertex> labels = {{{nan, 1.0f}, white}, {{8.0f, 1.0f}, white}, {{8.0f, 9.0f}, white},
                                       {{1.0f, 1.0f}, white}, {{inf, 1.0f}, white}, {{8.0f, 9.0f}, white},
                                       {{1.0f, 1.0f}, white}, {{3e9f, 1.0f}, white}, {{8.0f, -3e9f}, white},
                                       {{1.0f, 1.0f}, white}, {{9.0f, 1.0f}, white}};  // and a trailing incomplete one
  lay_labels(labels, image);
  EXPECT_EQ(image.rgb, blank(16, 16, 7).rgb);
}

TEST(FinishFrame, RefusesBuffersThatDoNotMatchTheSize) {
  ReadBackFrame frame = as_read_back(blank(4, 4, 9));
  frame.width_px = 5;
  RgbImage out;
  EXPECT_THROW(finish_frame(frame, out), std::invalid_argument);
  frame.width_px = 4;
  frame.labels.resize(2);  // not a whole triangle
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

// Frame k: a flat picture of grey level 3 k (distinct up to 85 frames).
ReadBackFrame numbered_frame(int k) { return as_read_back(blank(9, 5, static_cast<std::uint8_t>(3 * k))); }

int grey_of_png(const std::filesystem::path& path) {
  int w = 0, h = 0, n = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &w, &h, &n, 3);
  if (pixels == nullptr) return -1;
  const int grey = pixels[0];
  stbi_image_free(pixels);
  return grey;
}

TEST(FrameFinisher, HandsFramesOverInOrderAndWritesEachFile) {
  std::vector<int> seen;  // only the sink touches it, one frame at a time
  const int count = 40;
  {
    FrameFinisher queue([&seen](const RgbImage& frame) { seen.push_back(frame.rgb[0]); });
    for (int k = 0; k < count; ++k) {
      ReadBackFrame frame = queue.spare_frame();
      frame = numbered_frame(k);
      queue.push(scratch_path(frame_file_name(k)), std::move(frame));
    }
    EXPECT_EQ(queue.written(), count);
  }
  ASSERT_EQ(seen.size(), static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    EXPECT_EQ(seen[static_cast<std::size_t>(k)], 3 * k) << "frame " << k << " out of order";
    EXPECT_EQ(grey_of_png(scratch_path(frame_file_name(k))), 3 * k);
  }
}

TEST(FrameFinisher, AFrameThatCannotBeWrittenStopsTheRunWithoutHangingTheSink) {
  long long handed = 0;
  FrameFinisher queue([&handed](const RgbImage&) { ++handed; });
  bool thrown = false;
  try {
    for (int k = 0; k < 30; ++k) {
      // Frame 5 has a size that does not match its buffer: finish_frame refuses it.
      ReadBackFrame frame = numbered_frame(k);
      if (k == 5) frame.width_px = 3;
      queue.push(scratch_path(frame_file_name(k)), std::move(frame));
    }
  } catch (const std::invalid_argument&) {
    thrown = true;
  }
  EXPECT_TRUE(thrown);
  EXPECT_LE(handed, 5) << "no frame after the failed one reaches the sink";
  EXPECT_FALSE(std::filesystem::exists(scratch_path(frame_file_name(5))));
}

}  // namespace
}  // namespace railjoint
