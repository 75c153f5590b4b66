#pragma once
// The overlay of the close, orthographic views (side and top): the block of
// labels, the impact line and border, the scale bars.

#include <string>

#include "renders/camera.h"
#include "renders/crossing_setup.h"
#include "renders/offscreen_renderer.h"
#include "sim/trajectory.h"

namespace railjoint {

/// Labels on opaque boxes: the time and the wheel's position, then
/// `view_lines` (the view's own key), at the bottom left; on an impact frame
/// (`current`) the impact line at the top left and an orange border; scale
/// bars at the bottom right, else top right, else none: a horizontal one in
/// true length and, with `vertical_bar`, a vertical one in true length drawn
/// k-fold. px_per_m: image pixels per drawn metre.
void append_close_view_labels(FrameDrawList& list, const CrossingSetup& setup, double t_s, const WheelSample& sample,
                              const Camera& camera, double px_per_m, const ImpactEvent* current,
                              const std::string& view_lines, bool vertical_bar);

}  // namespace railjoint
