#include "renders/label_raster.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace railjoint {

namespace {

// A colour channel in [0, 1] as the framebuffer's byte, the way llvmpipe
// (Mesa's lp_build_clamped_float_to_unsigned_norm) converts it: x 255/256 +
// 2^15 in single precision leaves round-to-nearest-even of 256 (x 255/256)
// in the mantissa's low 8 bits. Ties go to even (0.10 x 255 = 25.5 gives 26,
// 0.3 gives 76), where rounding half up would differ from GL's labels.
std::uint8_t unorm8(float x) {
  volatile float scaled = std::clamp(x, 0.0f, 1.0f) * (255.0f / 256.0f);  // (no fused multiply-add)
  const float biased = scaled + 32768.0f;
  return static_cast<std::uint8_t>(std::bit_cast<std::uint32_t>(biased) & 0xFFu);
}

// Coordinates in 1/256 of a pixel, as llvmpipe snaps a vertex (8 bits below
// the pixel): every edge test below is then exact integer arithmetic.
constexpr std::int64_t kSub = 256;
constexpr double kFarthestPx = 1048576.0;  // 2^20: products of differences stay far inside 64 bits

struct Fixed {
  std::int64_t x, y;
};

// llvmpipe rounds to nearest, ties to even, in GL's window coordinates,
// whose y runs up from the image's bottom edge: y is snapped as
// height - y and turned back, so a corner on a 1/512 boundary goes the way
// GL's does (rounding y down the image instead differed in most such triangles).
bool snap(const Eigen::Vector2f& p, int height_px, Fixed& out) {
  if (!(std::abs(p.x()) <= kFarthestPx) || !(std::abs(p.y()) <= kFarthestPx)) return false;  // NaN fails too
  const double y_up = static_cast<double>(height_px) - static_cast<double>(p.y());
  out = {static_cast<std::int64_t>(std::nearbyint(static_cast<double>(p.x()) * kSub)),
         height_px * kSub - static_cast<std::int64_t>(std::nearbyint(y_up * kSub))};
  return true;
}

// floor(n / d) and ceil(n / d) for d > 0.
std::int64_t floor_div(std::int64_t n, std::int64_t d) { return n >= 0 ? n / d : -((-n + d - 1) / d); }
std::int64_t ceil_div(std::int64_t n, std::int64_t d) { return -floor_div(-n, d); }

void lay_triangle(const OverlayVertex* v, RgbImage& image) {
  std::array<Fixed, 3> p;
  for (int k = 0; k < 3; ++k) {
    if (!snap(v[k].position_px, image.height_px, p[static_cast<std::size_t>(k)])) return;
  }
  const std::int64_t area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
  if (area == 0) return;  // degenerate: GL draws nothing either
  const std::int64_t sign = area > 0 ? 1 : -1;
  // Pixel (i, j) has its centre at (256 i + 128, 256 j + 128). Each edge
  // p -> q gives E(c) = sign * cross(q - p, c - p), positive inside; along a
  // row E is linear in i: E = e0 + a i.
  struct Edge {
    std::int64_t a;         // dE/di
    std::int64_t dy_coeff;  // dE/d(centre y) = sign * (q.x - p.x)
    std::int64_t at_origin;  // E at the centre (128, 128) of pixel (0, 0)
    std::int64_t least;     // E must be >= this: 0 where a centre on the edge is covered, else 1
  };
  std::array<Edge, 3> edges;
  for (std::size_t k = 0; k < 3; ++k) {
    const Fixed& a = p[k];
    const Fixed& b = p[(k + 1) % 3];
    const std::int64_t dx = sign * (b.x - a.x), dy = sign * (b.y - a.y);
    // The inward normal is (-dy, dx): a left edge has -dy > 0; a horizontal
    // edge with the triangle above it (y down) has dx < 0.
    const bool tie_covered = -dy > 0 || (dy == 0 && dx < 0);
    edges[k] = {-dy * kSub, dx, dx * (128 - a.y) - dy * (128 - a.x), tie_covered ? 0 : 1};
  }
  const std::int64_t lo_y = std::min({p[0].y, p[1].y, p[2].y}), hi_y = std::max({p[0].y, p[1].y, p[2].y});
  // Rows whose centres lie within the triangle's height (the edge tests decide the rest).
  const std::int64_t first_row = std::max<std::int64_t>(0, ceil_div(lo_y - 128, kSub));
  const std::int64_t last_row = std::min<std::int64_t>(image.height_px - 1, floor_div(hi_y - 128, kSub));
  const std::uint8_t rgb[3] = {unorm8(v[0].colour[0]), unorm8(v[0].colour[1]), unorm8(v[0].colour[2])};
  const std::size_t stride = static_cast<std::size_t>(image.width_px) * 3;
  for (std::int64_t row = first_row; row <= last_row; ++row) {
    std::int64_t first = 0, last = image.width_px - 1;
    for (const Edge& e : edges) {
      const std::int64_t e0 = e.at_origin + e.dy_coeff * kSub * row;  // E at column 0 of this row
      if (e.a > 0) {
        first = std::max(first, ceil_div(e.least - e0, e.a));
      } else if (e.a < 0) {
        last = std::min(last, floor_div(e0 - e.least, -e.a));
      } else if (e0 < e.least) {
        last = -1;  // a horizontal edge with the whole row outside it
      }
    }
    std::uint8_t* out = image.rgb.data() + static_cast<std::size_t>(row) * stride;
    for (std::int64_t col = first; col <= last; ++col) {
      std::uint8_t* pixel = out + 3 * static_cast<std::size_t>(col);
      pixel[0] = rgb[0];
      pixel[1] = rgb[1];
      pixel[2] = rgb[2];
    }
  }
}

}  // namespace

void lay_labels(const std::vector<OverlayVertex>& triangles, RgbImage& image) {
  for (std::size_t i = 0; i + 3 <= triangles.size(); i += 3) lay_triangle(&triangles[i], image);
}

}  // namespace railjoint
