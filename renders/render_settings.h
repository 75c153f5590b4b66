#pragma once
// What the off-screen renderer is asked to draw: image size, frame rate in
// SIMULATED time, time window, vertical exaggeration and view. A plain struct
// without any GL, so the scene loader can fill it from a [render] section and
// a build without a GL back end still compiles everything that mentions it.

#include <optional>
#include <string>

namespace railjoint {

/// How edges are smoothed (docs/rendering.md, "Frame times", says what each costs).
enum class Antialiasing {
  none,  ///< one sample a pixel: staircase edges
  fxaa,  ///< fast approximate anti-aliasing: one pass over the drawn picture that blends across edges it finds
  msaa,  ///< 4 samples a pixel (the most llvmpipe offers), resolved to their mean: exact coverage, slow
};

/// Which way the camera looks.
enum class RenderView {
  side,         ///< orthographic, looking along +y from the y < 0 side: x to the right, z up
  top,          ///< orthographic, looking down -z: x to the right, y up (like thesis figure 4.8)
  perspective,  ///< perspective from behind, beside and above the wheel, following it
};

// Limits shared by check_render_settings() and the scene reader, so both say
// the same thing about the same key.
inline constexpr long long kMinImageSidePx = 16;
inline constexpr long long kMaxImageSidePx = 8192;
inline constexpr double kMinExaggeration = 1.0;
inline constexpr double kMaxExaggeration = 1e4;
/// Default visible width of the side and perspective views [m]: the region
/// around the contact, where the millimetre geometry (the V, the step at the
/// cut, the pivot about the corner) lies. The wheel is far larger than that.
inline constexpr double kDefaultContactViewWidth_m = 0.12;
/// A guard against a typo in fps or the window writing millions of files.
inline constexpr long long kMaxFrameCount = 100000;  // frame_%05d.png names up to 99999

struct RenderSettings {
  int width_px = 1280;
  int height_px = 720;
  /// Frames per SIMULATED second. Frames are taken at t_start + k / fps,
  /// independent of the physics step; 20000 gives slow motion of the impact.
  double fps = 20000.0;
  /// Time window [s]; absent = the first / last recorded sample of the trajectory.
  std::optional<double> t_start_s;
  std::optional<double> t_end_s;
  /// Vertical exaggeration k: heights are drawn as z_ref + k (z - z_ref), so the
  /// millimetre dip and step show under a metre-sized wheel. The same map is
  /// applied to everything, the wheel included (it is drawn as an ellipse k
  /// times taller than wide), so nothing overlaps that does not overlap in
  /// reality (see VerticalExaggeration).
  double exaggeration = 20.0;
  /// The height that exaggeration keeps fixed [m]: 0 = the rail top at the V bottom.
  double reference_z_m = 0.0;
  RenderView view = RenderView::side;
  /// true: the camera moves with the wheel along x; false: it stays centred on
  /// the middle of the wheel's x range over the time window.
  bool follow_wheel = true;
  /// Width of the visible world [m] (perspective: at the distance of the point
  /// looked at). Absent: side and perspective views show the contact region,
  /// kDefaultContactViewWidth_m wide around the wheel's lowest point; the top
  /// view shows the rail head, 3 rail widths high.
  std::optional<double> view_width_m;
  /// Edge smoothing of the 3-D pictures (labels are drawn after it, crisp).
  Antialiasing antialiasing = Antialiasing::fxaa;
  /// Also write the crossing as an animated glTF 2.0 file, crossing.glb
  /// (renders/crossing_gltf.h), for any glTF viewer or Blender.
  bool gltf = true;
  /// Assemble crossing.mp4 and crossing.gif from the frames when ffmpeg is on PATH.
  bool ffmpeg = true;
  /// Playback rate of the assembled videos [frames per wall-clock second].
  double video_fps = 25.0;
};

const char* to_string(RenderView view);
const char* to_string(Antialiasing antialiasing);

/// Throws InputError (key "render.<name>", allowed range in the message)
/// for settings the renderer cannot honour.
void check_render_settings(const RenderSettings& settings);

}  // namespace railjoint
