#include "scenes/render_section.h"

#include <sstream>

#include "support/input_error.h"

namespace railjoint {

RenderSettings read_render_section(SectionReader& in) {
  RenderSettings render;
  render.width_px = static_cast<int>(in.integer("width", render.width_px, kMinImageSidePx, kMaxImageSidePx));
  render.height_px = static_cast<int>(in.integer("height", render.height_px, kMinImageSidePx, kMaxImageSidePx));
  // Frames per simulated second: 1e6 is a frame per microsecond of slow
  // motion, 1 a frame per simulated second (a run lasts milliseconds).
  render.fps = in.number("fps", render.fps, Range::closed(1.0, 1e6, "1/simulated s"));
  // On the outputs' clock (t = 0 when the centre passes the predicted
  // impact, sim/time_origin.h), so negative before it; a run lasts at most
  // 1e6 steps of at most 0.01 s (scenes/sim_section.h): 1e4 s either way.
  render.t_start_s = in.optional_number("t_start", Range::closed(-1e4, 1e4, "s"));
  render.t_end_s = in.optional_number("t_end", Range::closed(-1e4, 1e4, "s"));
  if (render.t_start_s && render.t_end_s && !(*render.t_end_s > *render.t_start_s)) {
    std::ostringstream message;
    message << "must be greater than render.t_start (" << *render.t_start_s << " s), got " << *render.t_end_s << " s";
    throw InputError(in.file(), in.qualified("t_end"), message.str());
  }
  render.exaggeration =
      in.number("exaggeration", render.exaggeration, Range::closed(kMinExaggeration, kMaxExaggeration));
  // Heights in a scene stay within 20 m of the rail top (a 10 m step under
  // a 10 m wheel at most).
  render.reference_z_m = in.number("reference_z", render.reference_z_m, Range::closed(-20.0, 20.0, "m"));
  const std::string view = in.choice("view", "side", {"side", "top", "perspective"});
  render.view = view == "top" ? RenderView::top : view == "perspective" ? RenderView::perspective : RenderView::side;
  render.follow_wheel = in.boolean("follow", render.follow_wheel);
  // From 0.1 mm: the GL coordinates are single precision, 1.2e-7 m apart a
  // metre from the origin, under a thousand positions across a narrower view.
  render.view_width_m = in.optional_number("view_width", Range::closed(1e-4, 100.0, "m"));
  const std::string antialias = in.choice("antialias", "fxaa", {"fxaa", "msaa", "none"});
  render.antialiasing = antialias == "msaa"   ? Antialiasing::msaa
                        : antialias == "none" ? Antialiasing::none
                                              : Antialiasing::fxaa;
  render.ffmpeg = in.boolean("ffmpeg", render.ffmpeg);
  render.gltf = in.boolean("gltf", render.gltf);
  render.video_fps = in.number("video_fps", render.video_fps, Range::closed(1.0, 240.0, "frames/s"));
  in.finish();
  return render;
}

}  // namespace railjoint
