#pragma once
// PNG output of rendered frames through libpng (Debian's libpng-dev), zlib at
// level 1, rows unfiltered, memory level 6: the fastest zlib setting found
// (render_benchmark BM_EncodePng); libpng's defaults cost several times more
// for files a few per cent smaller.

#include <filesystem>

#include "renders/rgb_image.h"

namespace railjoint {

/// Writes `image` to `path`. Throws std::invalid_argument when the image's
/// size and pixel data disagree, std::runtime_error naming the file when it
/// cannot be opened or libpng fails (a short write included).
void write_png(const std::filesystem::path& path, const RgbImage& image);

}  // namespace railjoint
