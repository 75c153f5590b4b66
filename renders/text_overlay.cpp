#include "renders/text_overlay.h"

#include <cstdio>

#include <stb_easy_font.h>

#include "support/no_negative_zero.h"

namespace railjoint {

std::string format_label(const char* pattern, double a, double b, double c, double d) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), pattern, a, b, c, d);
  return without_negative_zeros(buffer);  // "t = -0.0000 ms" for an impact at -1.7e-12 s reads as a sign
}

void append_rectangle(std::vector<OverlayVertex>& out, float x0, float y0, float x1, float y1,
                      const Eigen::Vector3f& colour) {
  const Eigen::Vector2f a(x0, y0), b(x1, y0), c(x1, y1), d(x0, y1);
  for (const auto& p : {a, b, c, a, c, d}) out.push_back({p, colour});
}

void append_line(std::vector<OverlayVertex>& out, const Eigen::Vector2f& a, const Eigen::Vector2f& b, float thickness,
                 const Eigen::Vector3f& colour) {
  const Eigen::Vector2f along = b - a;
  if (!(along.norm() > 0.0f)) return;
  const Eigen::Vector2f across = Eigen::Vector2f(-along.y(), along.x()).normalized() * (0.5f * thickness);
  const Eigen::Vector2f a0 = a - across, a1 = a + across, b0 = b - across, b1 = b + across;
  for (const Eigen::Vector2f& p : {a0, b0, b1, a0, b1, a1}) out.push_back({p, colour});
}

void append_outline(std::vector<OverlayVertex>& out, float x0, float y0, float x1, float y1, float t,
                    const Eigen::Vector3f& colour) {
  append_rectangle(out, x0, y0, x1, y0 + t, colour);
  append_rectangle(out, x0, y1 - t, x1, y1, colour);
  append_rectangle(out, x0, y0 + t, x0 + t, y1 - t, colour);
  append_rectangle(out, x1 - t, y0 + t, x1, y1 - t, colour);
}

void append_border(std::vector<OverlayVertex>& out, int width_px, int height_px, float t,
                   const Eigen::Vector3f& colour) {
  append_outline(out, 0.0f, 0.0f, static_cast<float>(width_px), static_cast<float>(height_px), t, colour);
}

Eigen::Vector2f text_size_px(const std::string& text, float scale) {
  std::string mutable_text = text;  // stb_easy_font takes char*
  return {scale * static_cast<float>(stb_easy_font_width(mutable_text.data())),
          scale * static_cast<float>(stb_easy_font_height(mutable_text.data()))};
}

void append_text(std::vector<OverlayVertex>& out, const std::string& text, float x_px, float y_px, float scale,
                 const Eigen::Vector3f& colour) {
  // stb_easy_font writes quads of 4 vertices of 16 bytes (x, y, z, rgba8);
  // it needs about 270 bytes per character.
  struct FontVertex {
    float x, y, z;
    unsigned char rgba[4];
  };
  std::vector<FontVertex> quads(text.size() * 300 / sizeof(FontVertex) + 64);
  std::string mutable_text = text;  // stb_easy_font takes char*
  const int count = stb_easy_font_print(0.0f, 0.0f, mutable_text.data(), nullptr, quads.data(),
                                        static_cast<int>(quads.size() * sizeof(FontVertex)));
  for (int q = 0; q < count; ++q) {
    const FontVertex* v = &quads[static_cast<std::size_t>(q) * 4];
    auto at = [&](int i) { return Eigen::Vector2f(x_px + scale * v[i].x, y_px + scale * v[i].y); };
    for (int i : {0, 1, 2, 0, 2, 3}) out.push_back({at(i), colour});
  }
}

}  // namespace railjoint
