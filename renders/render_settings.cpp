#include "renders/render_settings.h"

#include <cmath>
#include <sstream>
#include <string>

#include "support/input_error.h"

namespace railjoint {

namespace {
std::string number(double x) {
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}
}  // namespace

const char* to_string(RenderView view) {
  switch (view) {
    case RenderView::side: return "side";
    case RenderView::top: return "top";
    case RenderView::perspective: return "perspective";
  }
  return "unknown";
}

const char* to_string(Antialiasing antialiasing) {
  switch (antialiasing) {
    case Antialiasing::none: return "none";
    case Antialiasing::fxaa: return "fxaa";
    case Antialiasing::msaa: return "msaa";
  }
  return "unknown";
}

void check_render_settings(const RenderSettings& s) {
  auto side = [](const char* key, int value) {
    if (value < kMinImageSidePx || value > kMaxImageSidePx) {
      std::ostringstream message;
      message << key << " must be in [" << kMinImageSidePx << ", " << kMaxImageSidePx << "] pixels, got " << value;
      throw InputError(key, message.str());
    }
  };
  side("render.width", s.width_px);
  side("render.height", s.height_px);
  if (!(s.fps > 0.0) || !std::isfinite(s.fps)) {
    throw InputError("render.fps", "render.fps (frames per simulated second) must be > 0, got " + number(s.fps));
  }
  if (!(s.exaggeration >= kMinExaggeration && s.exaggeration <= kMaxExaggeration)) {
    throw InputError("render.exaggeration",
                         "render.exaggeration must be in [1, 10000], got " + number(s.exaggeration));
  }
  if (!std::isfinite(s.reference_z_m)) throw InputError("render.reference_z", "render.reference_z must be finite");
  if (s.t_start_s && !std::isfinite(*s.t_start_s)) throw InputError("render.t_start", "render.t_start must be finite");
  if (s.t_end_s && !std::isfinite(*s.t_end_s)) throw InputError("render.t_end", "render.t_end must be finite");
  if (s.t_start_s && s.t_end_s && !(*s.t_end_s > *s.t_start_s)) {
    std::ostringstream message;
    message << "render.t_end (" << number(*s.t_end_s) << " s) must be greater than render.t_start ("
            << number(*s.t_start_s) << " s)";
    throw InputError("render.t_end", message.str());
  }
  if (s.view_width_m && !(*s.view_width_m > 0.0 && std::isfinite(*s.view_width_m))) {
    throw InputError("render.view_width", "render.view_width must be > 0 m");
  }
  if (!(s.video_fps > 0.0) || !std::isfinite(s.video_fps)) {
    throw InputError("render.video_fps", "render.video_fps must be > 0 frames per second");
  }
}

}  // namespace railjoint
