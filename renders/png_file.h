#pragma once
// PNG output of rendered frames. libpng (Debian's libpng-dev) writes the
// container (signature, IHDR, IEND, every chunk's CRC); the pixels are
// deflated by Intel's ISA-L (Debian's libisal-dev) at its level 1, rows
// unfiltered, into IDAT chunks of 1 MiB. On 2026-11-25's machine
// (render_benchmark BM_EncodePng, 1280 x 720) ISA-L level 1 took 0.50, 0.47
// and 1.29 ms for a side, top and perspective frame where zlib level 1 took
// 3.23, 3.02 and 5.51 ms, for files 4, 12 and 2 % bigger: zlib had been the
// largest share of a written frame's CPU (27 %). zlib through libpng stays
// as the reference the benchmark compares against, at the fastest setting
// found for it (level 1, no row filter, memory level 6; the "up" filter,
// zlib's run-length strategy, other memory levels and libpng's defaults were
// all slower).

#include <cstdint>
#include <filesystem>
#include <vector>

#include "renders/rgb_image.h"

namespace railjoint {

/// Which deflate encoder writes the pixels, and at what level.
struct PngSpeed {
  enum class Deflate { isal, zlib };
  Deflate deflate = Deflate::isal;
  int level = 1;  ///< ISA-L 0-3, zlib 0-9
};

/// The PNG file's bytes for `image`; throws std::invalid_argument when the
/// image's size and pixel data disagree or the level is out of range,
/// std::runtime_error when libpng or ISA-L fails.
std::vector<std::uint8_t> encode_png(const RgbImage& image, const PngSpeed& speed = {});

/// Writes `image` to `path`; throws std::runtime_error naming the file when
/// encoding or writing fails. Safe to call from several threads at once.
void write_png(const std::filesystem::path& path, const RgbImage& image, const PngSpeed& speed = {});

}  // namespace railjoint
