#include "renders/fxaa.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace railjoint {

namespace {


// Bilinear sample of the picture at (x, y) in pixel-centre coordinates (pixel
// (i, j) has its centre at (i, j)), clamped to the picture; weights in 1/256ths.
inline std::array<float, 3> sample(const RgbImage& image, float x, float y) {
  x = std::clamp(x, 0.0f, static_cast<float>(image.width_px - 1));
  y = std::clamp(y, 0.0f, static_cast<float>(image.height_px - 1));
  const int x0 = std::min(static_cast<int>(x), image.width_px - 2), y0 = std::min(static_cast<int>(y), image.height_px - 2);
  const int fx = static_cast<int>((x - static_cast<float>(x0)) * 256.0f), fy = static_cast<int>((y - static_cast<float>(y0)) * 256.0f);
  const std::uint8_t* a = image.pixel(x0, y0);
  const std::uint8_t* c = image.pixel(x0, y0 + 1);
  std::array<float, 3> out{};
  for (int k = 0; k < 3; ++k) {
    const int top = (256 - fx) * a[k] + fx * a[k + 3], bottom = (256 - fx) * c[k] + fx * c[k + 3];
    out[static_cast<std::size_t>(k)] = static_cast<float>((256 - fy) * top + fy * bottom) * (1.0f / 65536.0f);
  }
  return out;
}

struct Blended {
  std::size_t offset;  // byte offset of the pixel
  std::array<std::uint8_t, 3> rgb;
};

}  // namespace

void apply_fxaa(RgbImage& image) {
  const int w = image.width_px, h = image.height_px;
  if (w < 3 || h < 3) return;
  const std::size_t stride = static_cast<std::size_t>(w);
  // Luma: the green channel, as FXAA's own fast path takes it (FXAA_GREEN_AS_LUMA);
  // every edge between the palette's colours differs in green.
  std::vector<std::uint8_t> l(stride * static_cast<std::size_t>(h));
  const std::uint8_t* rgb = image.rgb.data();
  for (std::size_t i = 0; i < l.size(); ++i) l[i] = rgb[3 * i + 1];
  // Blends read the unfiltered picture: collect them, write them after.
  std::vector<Blended> blended;
  std::vector<std::uint8_t> edge(stride);
  for (int row = 1; row + 1 < h; ++row) {
    const std::uint8_t* up = l.data() + static_cast<std::size_t>(row - 1) * stride;
    const std::uint8_t* mid = up + stride;
    const std::uint8_t* down = mid + stride;
    // Which pixels of the row lie on an edge: the luma range of the pixel and
    // its diagonal neighbours reaches FXAA's thresholds (0.0312, 1/8 of the
    // brightest). A branch-free loop the compiler runs 32 pixels at a time.
    for (int col = 1; col + 1 < w; ++col) {
      const std::uint8_t a = up[col - 1], b = up[col + 1], c = down[col - 1], d = down[col + 1], e = mid[col];
      const std::uint8_t lo = std::min(std::min(std::min(a, b), std::min(c, d)), e);
      const std::uint8_t hi = std::max(std::max(std::max(a, b), std::max(c, d)), e);
      const std::uint8_t range = static_cast<std::uint8_t>(hi - lo);
      const std::uint8_t threshold = std::max(static_cast<std::uint8_t>(8), static_cast<std::uint8_t>(hi >> 3));
      edge[static_cast<std::size_t>(col)] = range >= threshold ? 1 : 0;
    }
    edge[0] = 0;
    edge[stride - 1] = 0;
    for (int col = 1; col + 1 < w; ++col) {
      if (col % 8 == 0 && col + 8 < w) {  // eight pixels without an edge at once
        std::uint64_t word;
        std::memcpy(&word, edge.data() + col, 8);
        if (word == 0) {
          col += 7;
          continue;
        }
      }
      if (edge[static_cast<std::size_t>(col)] == 0) continue;
      const int m = mid[col], nw = up[col - 1], ne = up[col + 1], sw = down[col - 1], se = down[col + 1];
      const int lo = std::min({m, nw, ne, sw, se}), hi = std::max({m, nw, ne, sw, se});
      // Direction along the edge (image rows grow downwards: "north" is row - 1).
      float dx = -static_cast<float>((nw + ne) - (sw + se)) / 255.0f;
      float dy = static_cast<float>((nw + sw) - (ne + se)) / 255.0f;
      const float reduce = std::max(static_cast<float>(nw + ne + sw + se) / 255.0f * (0.25f / 8.0f), 1.0f / 128.0f);
      const float scale = 1.0f / (std::min(std::abs(dx), std::abs(dy)) + reduce);
      dx = std::clamp(dx * scale, -8.0f, 8.0f);
      dy = std::clamp(dy * scale, -8.0f, 8.0f);
      const float x = static_cast<float>(col), y = static_cast<float>(row);
      const auto a1 = sample(image, x + dx * (1.0f / 3.0f - 0.5f), y + dy * (1.0f / 3.0f - 0.5f));
      const auto a2 = sample(image, x + dx * (2.0f / 3.0f - 0.5f), y + dy * (2.0f / 3.0f - 0.5f));
      const auto b1 = sample(image, x - 0.5f * dx, y - 0.5f * dy);
      const auto b2 = sample(image, x + 0.5f * dx, y + 0.5f * dy);
      std::array<float, 3> a{}, b{};
      for (std::size_t k = 0; k < 3; ++k) {
        a[k] = 0.5f * (a1[k] + a2[k]);
        b[k] = 0.5f * a[k] + 0.25f * (b1[k] + b2[k]);
      }
      const float lb = b[1];  // green, as the luma above
      const std::array<float, 3>& chosen = (lb < static_cast<float>(lo) || lb > static_cast<float>(hi) + 1.0f) ? a : b;
      Blended out{(static_cast<std::size_t>(row) * stride + static_cast<std::size_t>(col)) * 3, {}};
      for (std::size_t k = 0; k < 3; ++k) out.rgb[k] = static_cast<std::uint8_t>(std::clamp(chosen[k], 0.0f, 255.0f) + 0.5f);
      blended.push_back(out);
    }
  }
  for (const Blended& b : blended) std::copy(b.rgb.begin(), b.rgb.end(), image.rgb.begin() + static_cast<std::ptrdiff_t>(b.offset));
}

}  // namespace railjoint
