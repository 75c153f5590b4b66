#pragma once
// An 8-bit RGB image with rows stored TOP FIRST (as PNG wants them; GL and
// OSMesa hand rows over bottom first, the renderer flips them).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace railjoint {

struct RgbImage {
  int width_px = 0;
  int height_px = 0;
  std::vector<std::uint8_t> rgb;  ///< width_px * height_px * 3 bytes, row 0 = top of the picture

  const std::uint8_t* pixel(int column, int row) const {
    return rgb.data() + (static_cast<std::size_t>(row) * static_cast<std::size_t>(width_px) +
                         static_cast<std::size_t>(column)) * 3;
  }
};

}  // namespace railjoint
