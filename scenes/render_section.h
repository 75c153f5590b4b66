#pragma once
// The [render] section of a scene file: what the off-screen renderer draws
// (renders/render_settings.h). A scene without [render] never creates a GL
// context. Keys (SI units unless the name says otherwise):
//   width, height   image size [px], integers in [16, 8192]        (1280 x 720)
//   fps             frames per SIMULATED second, > 0               (20000: slow motion)
//   t_start, t_end  time window [s], t_end > t_start; absent = the whole trajectory
//   exaggeration    vertical exaggeration of everything drawn, the wheel included, [1, 10000] (20)
//   reference_z     height the exaggeration keeps fixed [m]        (0: rail top at the V bottom)
//   view            "side" | "top" | "perspective"                 ("side")
//   follow          camera follows the wheel along x               (true)
//   view_width      visible width [m], > 0; absent = 0.12 m around the contact (side,
//                   perspective), 3 rail widths high (top)
//   ffmpeg          assemble crossing.mp4 and crossing.gif when ffmpeg is on PATH (true)
//   video_fps       playback rate of those videos [1/s], > 0       (25)

#include "renders/render_settings.h"
#include "scenes/section_reader.h"

namespace railjoint {

/// Reads every key above (range-checked, InputError naming "render.<key>"),
/// then rejects unknown keys (finish()).
RenderSettings read_render_section(SectionReader& in);

}  // namespace railjoint
