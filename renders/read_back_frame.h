#pragma once
// A frame as the GL context hands it over (RGBA, rows bottom first), before
// the CPU's share of the work: turning it into RGB rows top first, FXAA, and
// laying the labels over the smoothed picture (renders/frame_finisher.h).

#include <cstdint>
#include <vector>

#include "renders/overlay_vertex.h"
#include "renders/rgb_image.h"

namespace railjoint {

struct ReadBackFrame {
  int width_px = 0;
  int height_px = 0;
  std::vector<std::uint8_t> picture_rgba;  ///< width x height RGBA, rows bottom first
  bool fxaa = false;                       ///< smooth the picture's edges before the labels go on
  /// With fxaa: the label triangles (FrameDrawList::overlay), laid over the
  /// smoothed picture by lay_labels (renders/label_raster.h). Without fxaa
  /// the labels are already in the picture.
  std::vector<OverlayVertex> labels;
};

/// The finished picture: RGB rows top first, FXAA applied if asked, then
/// the labels laid over it, crisp. Uses no GL: safe on any
/// thread. Throws std::invalid_argument when the buffers do not match the
/// size or a label triangle is not whole.
void finish_frame(const ReadBackFrame& frame, RgbImage& out);

}  // namespace railjoint
