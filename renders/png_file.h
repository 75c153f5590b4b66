#pragma once
// PNG output of rendered frames (libpng, Debian's libpng-dev), set for
// speed: zlib level 1 with no row filter, zlib's hash table at memory level 6
// (render_benchmark BM_EncodePng; the times are in README.md, "Frame
// times"). The "up" filter (a row equal to the one above becomes zeros) gave
// smaller flat frames (32 against 41 kB for a side view) but cost more in
// every view and made the shaded perspective frame bigger (162 against
// 140 kB); memory level 8, zlib's default, cost 7-18 % more for the same
// bytes; zlib's run-length-only strategy and libpng's defaults (zlib 6,
// adaptive filters) are slower still.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "renders/rgb_image.h"

namespace railjoint {

/// How hard the encoder works: zlib level (0-9), strategy and row filter.
struct PngSpeed {
  int zlib_level = 1;
  int memory_level = 6;  ///< zlib's memLevel (1-9): its hash table has 2^(memory_level + 7) entries
  bool run_length_only = false;  ///< zlib's Z_RLE strategy (no string matching)
  enum class Filter { none, up, sub, all } filter = Filter::none;
};

/// The PNG file's bytes for `image`; throws std::invalid_argument when the
/// image's size and pixel data disagree, std::runtime_error when libpng fails.
std::vector<std::uint8_t> encode_png(const RgbImage& image, const PngSpeed& speed = {});

/// Writes `image` to `path`; throws std::runtime_error naming the file when
/// encoding or writing fails. Safe to call from several threads at once.
void write_png(const std::filesystem::path& path, const RgbImage& image, const PngSpeed& speed = {});

}  // namespace railjoint
