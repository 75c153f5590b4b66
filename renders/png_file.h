#pragma once
// PNG output of rendered frames through libpng (Debian's libpng-dev), zlib at
// level 1, rows unfiltered, memory level 6: the fastest zlib setting found
// (render_benchmark BM_EncodePng); libpng's defaults cost several times more
// for files a few per cent smaller.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "renders/rgb_image.h"

namespace railjoint {

/// The PNG file's bytes for `image`; throws std::invalid_argument when the
/// image's size and pixel data disagree, std::runtime_error when libpng fails.
std::vector<std::uint8_t> encode_png(const RgbImage& image);

/// Writes `image` to `path`; throws std::runtime_error naming the file when
/// encoding or writing fails. Safe to call from several threads at once.
void write_png(const std::filesystem::path& path, const RgbImage& image);

}  // namespace railjoint
