#pragma once
// Labels and frame borders drawn over the picture, as triangles in pixel
// coordinates (origin top-left, y down) for OffscreenRenderer's overlay.
// Text uses stb_easy_font: ASCII only, built from quads, no texture.

#include <string>
#include <vector>

#include "renders/offscreen_renderer.h"

namespace railjoint {

/// Appends `text` ('\n' starts a new line) with its top-left corner at (x, y),
/// each font pixel `scale` image pixels wide.
void append_text(std::vector<OverlayVertex>& out, const std::string& text, float x_px, float y_px, float scale,
                 const Eigen::Vector3f& colour);

/// Width and height of `text` as append_text draws it [px].
Eigen::Vector2f text_size_px(const std::string& text, float scale);

/// printf of up to four numbers into a label (at most 255 characters), no
/// negative zero (support/no_negative_zero.h).
std::string format_label(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0);

/// Appends a filled rectangle [x0, x1] x [y0, y1].
void append_rectangle(std::vector<OverlayVertex>& out, float x0_px, float y0_px, float x1_px, float y1_px,
                      const Eigen::Vector3f& colour);

/// Appends a straight line from a to b, `thickness_px` wide (a thin quad).
void append_line(std::vector<OverlayVertex>& out, const Eigen::Vector2f& a_px, const Eigen::Vector2f& b_px,
                 float thickness_px, const Eigen::Vector3f& colour);

/// Appends the outline of the rectangle [x0, x1] x [y0, y1], `thickness_px` wide, inside it.
void append_outline(std::vector<OverlayVertex>& out, float x0_px, float y0_px, float x1_px, float y1_px,
                    float thickness_px, const Eigen::Vector3f& colour);

/// Appends a frame of the given thickness around the whole image.
void append_border(std::vector<OverlayVertex>& out, int width_px, int height_px, float thickness_px,
                   const Eigen::Vector3f& colour);

}  // namespace railjoint
