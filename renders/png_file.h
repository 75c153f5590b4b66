#pragma once
// PNG output of rendered frames (libpng, Debian's libpng-dev). Rendered
// frames are mostly flat colour, so the encoder is set for speed: zlib level 1
// over the "up" row filter (a row equal to the one above becomes zeros). At
// 1280 x 720 (render_benchmark, CPU per frame) that took 5.2 ms for a 32 kB
// side view, against 5.7 ms and 57 kB with zlib's run-length-only strategy
// and 22 ms and 17 kB with libpng's defaults (zlib 6, adaptive filters).

#include <cstdint>
#include <filesystem>
#include <vector>

#include "renders/rgb_image.h"

namespace railjoint {

/// How hard the encoder works: zlib level (0-9), strategy and row filter.
struct PngSpeed {
  int zlib_level = 1;
  bool run_length_only = false;  ///< zlib's Z_RLE strategy (no string matching)
  enum class Filter { none, up, sub, all } filter = Filter::up;
};

/// The PNG file's bytes for `image`; throws std::invalid_argument when the
/// image's size and pixel data disagree, std::runtime_error when libpng fails.
std::vector<std::uint8_t> encode_png(const RgbImage& image, const PngSpeed& speed = {});

/// Writes `image` to `path`; throws std::runtime_error naming the file when
/// encoding or writing fails. Safe to call from several threads at once.
void write_png(const std::filesystem::path& path, const RgbImage& image, const PngSpeed& speed = {});

}  // namespace railjoint
