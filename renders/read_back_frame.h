#pragma once
// A frame as the GL context hands it over (RGBA, rows bottom first), before
// the CPU's share of the work: RGB rows top first, FXAA, and the labels over
// the smoothed picture, crisp (finish_frame).

#include <cstdint>
#include <vector>

#include "renders/rgb_image.h"

namespace railjoint {

struct ReadBackFrame {
  int width_px = 0;
  int height_px = 0;
  std::vector<std::uint8_t> picture_rgba;  ///< width x height RGBA, rows bottom first, without the labels
  bool fxaa = false;                       ///< smooth the picture's edges before the labels go on
  /// The labels (FrameDrawList::overlay) as GL drew them on a transparent
  /// ground, like picture_rgba: alpha 255 where a label covers the pixel,
  /// 0 elsewhere. Empty when the frame has no labels.
  std::vector<std::uint8_t> labels_rgba;
};

/// The finished picture: RGB rows top first, FXAA applied if asked, then
/// the labels laid over it. Uses no GL. Throws std::invalid_argument when
/// the buffers do not match the size.
void finish_frame(const ReadBackFrame& frame, RgbImage& out);

}  // namespace railjoint
