#include "renders/read_back_frame.h"

#include <bit>
#include <cstring>
#include <stdexcept>

#include "renders/fxaa.h"
#include "renders/label_raster.h"

namespace railjoint {

namespace {

// One row of RGBA to RGB, four pixels (16 bytes in, 12 out) a step: the
// byte-by-byte loop cost as much as FXAA itself (perf, render_benchmark).
void rgba_row_to_rgb(const std::uint8_t* src, std::uint8_t* dst, std::size_t pixels) {
  std::size_t x = 0;
  if constexpr (std::endian::native == std::endian::little) {
    for (; x + 4 <= pixels; x += 4) {
      std::uint32_t p[4];
      std::memcpy(p, src + 4 * x, 16);
      const std::uint32_t q[3] = {(p[0] & 0xFFFFFFu) | (p[1] << 24), ((p[1] >> 8) & 0xFFFFu) | (p[2] << 16),
                                  ((p[2] >> 16) & 0xFFu) | (p[3] << 8)};
      std::memcpy(dst + 3 * x, q, 12);
    }
  }
  for (; x < pixels; ++x) std::memcpy(dst + 3 * x, src + 4 * x, 3);
}

}  // namespace

void finish_frame(const ReadBackFrame& frame, RgbImage& out) {
  const std::size_t w = static_cast<std::size_t>(frame.width_px), h = static_cast<std::size_t>(frame.height_px);
  if (frame.width_px <= 0 || frame.height_px <= 0 || frame.picture_rgba.size() != w * h * 4) {
    throw std::invalid_argument("finish_frame: the read-back buffer does not match the frame size");
  }
  if (frame.labels.size() % 3 != 0) throw std::invalid_argument("finish_frame: a label triangle is not whole");
  out.width_px = frame.width_px;
  out.height_px = frame.height_px;
  out.rgb.resize(w * h * 3);
  // GL rows start at the bottom of the picture; PNG rows at the top.
  for (std::size_t row = 0; row < h; ++row) {
    rgba_row_to_rgb(frame.picture_rgba.data() + (h - 1 - row) * w * 4, out.rgb.data() + row * w * 3, w);
  }
  if (frame.fxaa) apply_fxaa(out);
  lay_labels(frame.labels, out);
}

}  // namespace railjoint
