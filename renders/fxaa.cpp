#include "renders/fxaa.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace railjoint {

namespace {

// The picture's bytes with its size, for the fixed-point samples below.
struct Picture {
  const std::uint8_t* rgb;
  int width_px, height_px;
  int max_x_256, max_y_256;  // the last pixel centre, in 1/256ths of a pixel
};

// Bilinear sample at (x, y) given in 1/256ths of a pixel, pixel-centre
// coordinates (pixel (i, j) has its centre at (256 i, 256 j)), clamped to the
// picture: each channel times 65536, added into `sum`. Integer arithmetic
// throughout: the float version of this sample was most of FXAA's time.
inline void add_sample(const Picture& p, int x_256, int y_256, int sum[3]) {
  x_256 = std::clamp(x_256, 0, p.max_x_256);
  y_256 = std::clamp(y_256, 0, p.max_y_256);
  const int x0 = std::min(x_256 >> 8, p.width_px - 2), y0 = std::min(y_256 >> 8, p.height_px - 2);
  const int fx = x_256 - 256 * x0, fy = y_256 - 256 * y0;
  const std::uint8_t* a = p.rgb + (static_cast<std::size_t>(y0) * static_cast<std::size_t>(p.width_px) +
                                   static_cast<std::size_t>(x0)) * 3;
  const std::uint8_t* c = a + static_cast<std::size_t>(p.width_px) * 3;
  for (int k = 0; k < 3; ++k) {
    const int top = (256 - fx) * a[k] + fx * a[k + 3], bottom = (256 - fx) * c[k] + fx * c[k + 3];
    sum[k] += (256 - fy) * top + fy * bottom;
  }
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
  blended.reserve(l.size() / 16);
  const Picture picture{image.rgb.data(), w, h, 256 * (w - 1), 256 * (h - 1)};
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
      // Two taps at +-1/6 of the direction (a) and two more at +-1/2 (b), in
      // 1/256ths of a pixel: a = their mean, b = the mean of all four.
      const int x_256 = 256 * col, y_256 = 256 * row;
      const int dx6 = static_cast<int>(dx * (256.0f / 6.0f)), dy6 = static_cast<int>(dy * (256.0f / 6.0f));
      const int dx2 = static_cast<int>(dx * 128.0f), dy2 = static_cast<int>(dy * 128.0f);
      int a[3] = {0, 0, 0};
      add_sample(picture, x_256 - dx6, y_256 - dy6, a);
      add_sample(picture, x_256 + dx6, y_256 + dy6, a);
      int b[3] = {a[0], a[1], a[2]};
      add_sample(picture, x_256 - dx2, y_256 - dy2, b);
      add_sample(picture, x_256 + dx2, y_256 + dy2, b);
      // a holds 2 x 65536 x the mean of its taps, b 4 x 65536 x the mean of its own.
      const int lb = b[1];  // green, as the luma above
      const bool b_leaves_range = lb < lo * (4 << 16) || lb > (hi + 1) * (4 << 16);
      Blended out{(static_cast<std::size_t>(row) * stride + static_cast<std::size_t>(col)) * 3, {}};
      for (std::size_t k = 0; k < 3; ++k) {
        out.rgb[k] = static_cast<std::uint8_t>(b_leaves_range ? (a[k] + (1 << 16)) >> 17 : (b[k] + (1 << 17)) >> 18);
      }
      blended.push_back(out);
    }
  }
  for (const Blended& b : blended) std::copy(b.rgb.begin(), b.rgb.end(), image.rgb.begin() + static_cast<std::ptrdiff_t>(b.offset));
}

}  // namespace railjoint
