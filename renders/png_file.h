#pragma once
// PNG output of rendered frames (stb_image_write, Debian's libstb).
// Rendered frames are mostly flat colour, so the encoder is set for speed:
// zlib effort 5 (stb's lowest; its default is 8) and no row filter instead
// of trying all five on every row. See render_benchmark.

#include <filesystem>

#include "renders/rgb_image.h"

namespace railjoint {

/// Writes `image` to `path`; throws std::runtime_error naming the file when
/// encoding or writing fails. Safe to call from several threads at once.
void write_png(const std::filesystem::path& path, const RgbImage& image);

}  // namespace railjoint
