#pragma once
// The labels (text, boxes, call-out lines: FrameDrawList::overlay) laid over
// a finished picture on the CPU, for frames smoothed by FXAA: the labels go
// on after the smoothing so they stay crisp. Drawing them with GL instead
// took a second pass on the drawing thread, the one serial step of a render
// (a clear, a draw and a read-back, about 2 ms of a perspective frame,
// render_benchmark BM_WrittenFrame); here they are laid by the frame
// finisher (renders/frame_finisher.h), covering the same pixels as
// llvmpipe does (label_raster_gl_test; on slanted edges llvmpipe settles a
// few per cent of exact ties the other way).

#include <vector>

#include "renders/overlay_vertex.h"
#include "renders/rgb_image.h"

namespace railjoint {

/// Lays `triangles` (three vertices each, pixel coordinates with the origin
/// at the image's top-left corner, y down; the first vertex's colour) over
/// `image`, as GL's rasteriser covers them: the corners snapped to 1/256 of a
/// pixel, a pixel covered when its centre lies inside the triangle, and a
/// centre on an edge covered when the edge is a left one, or a horizontal
/// one with the triangle above it (GL's origin is at the bottom-left
/// corner), so abutting triangles share no pixel and leave none out. Later
/// triangles cover earlier ones; a trailing incomplete one is ignored, as
/// is one with a corner that is not finite or lies more than 2^20 pixels
/// out.
void lay_labels(const std::vector<OverlayVertex>& triangles, RgbImage& image);

}  // namespace railjoint
