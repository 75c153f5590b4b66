#pragma once
// What `railjoint render` (and `simulate` with [render]) drew: GL version,
// view, window, frames, frame time and videos, one line each.

#include <cstdio>

#include "scenes/cli/crossing_drawing.h"

namespace railjoint {

void print_render_report(const RenderedCrossing& rendered, std::FILE* log);

}  // namespace railjoint
