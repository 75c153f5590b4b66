#pragma once
// Fast approximate anti-aliasing (after T. Lottes' FXAA, the short PC form)
// on the CPU, over a finished RGB picture: where the luma of a pixel's four
// diagonal neighbours spans an edge, the pixel is blended along the edge's
// direction; elsewhere it is left alone. llvmpipe has no cheap way to smooth
// edges: 4x multisampling costs five times the plain frame, the same filter
// as a shader pass (texture fetches) even more; here it costs a few
// milliseconds on one core (render_benchmark), after each frame is drawn
// (renders/read_back_frame.h). Fixed-point taps, rounded the same way
// either side of a pixel: the filter commutes with mirroring, byte for byte.

#include "renders/rgb_image.h"

namespace railjoint {

/// Smooths the edges of `image` in place. The outermost rows and columns are left as they are.
void apply_fxaa(RgbImage& image);

}  // namespace railjoint
