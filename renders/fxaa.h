#pragma once
// Fast approximate anti-aliasing (after T. Lottes' FXAA, the short PC form)
// on the CPU, over a finished RGB picture: where the luma of a pixel's four
// diagonal neighbours spans an edge, the pixel is blended along the edge's
// direction; elsewhere it is left alone. On llvmpipe that is cheaper than 4x
// multisampling or the same filter as a shader pass. Fixed-point taps,
// rounded the same way either side of a pixel: the filter commutes with
// mirroring, byte for byte.

#include "renders/rgb_image.h"

namespace railjoint {

/// Smooths the edges of `image` in place. The outermost rows and columns are left as they are.
void apply_fxaa(RgbImage& image);

}  // namespace railjoint
