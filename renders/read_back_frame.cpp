#include "renders/read_back_frame.h"

#include <stdexcept>

#include "renders/fxaa.h"

namespace railjoint {

void finish_frame(const ReadBackFrame& frame, RgbImage& out) {
  const std::size_t w = static_cast<std::size_t>(frame.width_px), h = static_cast<std::size_t>(frame.height_px);
  if (frame.width_px <= 0 || frame.height_px <= 0 || frame.picture_rgba.size() != w * h * 4 ||
      (!frame.labels_rgba.empty() && frame.labels_rgba.size() != w * h * 4)) {
    throw std::invalid_argument("finish_frame: the read-back buffer does not match the frame size");
  }
  out.width_px = frame.width_px;
  out.height_px = frame.height_px;
  out.rgb.resize(w * h * 3);
  // GL rows start at the bottom of the picture; PNG rows at the top.
  for (std::size_t row = 0; row < h; ++row) {
    const std::uint8_t* src = frame.picture_rgba.data() + (h - 1 - row) * w * 4;
    std::uint8_t* dst = out.rgb.data() + row * w * 3;
    for (std::size_t x = 0; x < w; ++x) {
      for (std::size_t c = 0; c < 3; ++c) dst[3 * x + c] = src[4 * x + c];
    }
  }
  if (frame.fxaa) apply_fxaa(out);
  if (frame.labels_rgba.empty()) return;
  for (std::size_t row = 0; row < h; ++row) {
    const std::uint8_t* src = frame.labels_rgba.data() + (h - 1 - row) * w * 4;
    std::uint8_t* dst = out.rgb.data() + row * w * 3;
    for (std::size_t x = 0; x < w; ++x) {
      if (src[4 * x + 3] == 0) continue;  // no label on this pixel
      for (std::size_t c = 0; c < 3; ++c) dst[3 * x + c] = src[4 * x + c];
    }
  }
}

}  // namespace railjoint
