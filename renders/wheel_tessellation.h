#pragma once
// How many sides the render wheel needs. The render mesh is a regular N-gon
// inscribed in the circle of radius R (geometry/wheel_mesh.h): its edges lie
// up to R (1 - cos(pi / N)) inside the circle. Under a vertical exaggeration
// k that gap is drawn k times taller at the contact, where the view is
// s = width_px / W pixels per metre (W the visible width, renders/camera.h):
// k s R (1 - cos(pi / N)) pixels. A polygon wheel that looks fine whole is
// visibly faceted, and seems to float above the rails, in the contact view
// (96 sides: 54 px at 1280 px over 0.12 m and k = 20).

#include "renders/render_settings.h"

namespace railjoint {

inline constexpr int kMinWheelRenderSegments = 64;
inline constexpr int kMaxWheelRenderSegments = 16384;

/// The smallest N that keeps that gap below `max_gap_px` (0.25 px: below
/// the anti-aliasing of an edge) in the side and perspective views of
/// `settings`, clamped to [kMinWheelRenderSegments, kMaxWheelRenderSegments].
/// W is settings.view_width_m, else kDefaultContactViewWidth_m (the top view,
/// which sees the wheel edge-on, is covered by the same bound since its default
/// width is larger). About 1,400 sides at 1280 px, 0.12 m, k = 20, R = 0.475 m.
int wheel_render_segments(const RenderSettings& settings, double wheel_radius_m, double max_gap_px = 0.25);

/// The smallest N for which a regular N-gon inscribed in a circle drawn
/// `radius_px` pixels wide stays within `max_gap_px` of it:
/// N >= pi / acos(1 - gap / r), clamped as above.
int polygon_sides_for_radius_px(double radius_px, double max_gap_px = 0.25);

}  // namespace railjoint
