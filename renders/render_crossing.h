#pragma once
// The renderer's entry point: frames of a recorded crossing written as PNG
// files, plus crossing.mp4 / crossing.gif when ffmpeg is on PATH.

#include <filesystem>
#include <optional>
#include <string>

#include "geometry/rail_joint_mesh.h"
#include "geometry/triangle_mesh.h"
#include "models/pressure_traversal.h"
#include "renders/render_settings.h"
#include "renders/video_files.h"
#include "sim/trajectory.h"

namespace railjoint {

struct RenderReport : VideoFiles {
  long long frames_written = 0;
  std::filesystem::path frame_pattern;  ///< <out_dir>/frame_%05d.png
  double render_ms_per_frame = 0.0;     ///< mean GL draw + read-back, on the calling thread [ms]
  double finish_ms_per_frame = 0.0;     ///< mean RGB rows + FXAA + labels [ms]
  double encode_ms_per_frame = 0.0;     ///< mean PNG encode + file write [ms]
  double frames_wall_s = 0.0;           ///< wall time from the first frame to the last file written [s]
  double video_wall_s = 0.0;            ///< wall time ffmpeg needed after the last frame [s]
  std::string gl_version;               ///< GL_VERSION of the context actually created
  std::string gl_renderer;              ///< GL_RENDERER (llvmpipe here)
  int overview_wheel_sides = 0;         ///< PerspectiveView::overview_wheel_sides, else 0
  std::optional<std::filesystem::path> gltf;  ///< <out_dir>/crossing.glb when settings.gltf
  long long gltf_keys = 0;                    ///< wheel keys in it
  double gltf_slow_motion = 1.0;              ///< its playback seconds per simulated second
};

/// Renders frames at t_start + k / settings.fps (see FrameWindow for the
/// count) into out_dir/frame_00000.png, frame_00001.png, ... (out_dir is
/// created), and with settings.gltf out_dir/crossing.glb (renders/crossing_gltf.h). Throws InputError for bad settings, std::invalid_argument for
/// bad meshes or an empty trajectory, std::runtime_error naming the folder when
/// out_dir cannot be created or a file in it written, and "rendering
/// unavailable: built without OSMesa" in a build without it. A missing ffmpeg is not an error:
/// the report says so and the frames stay. An ffmpeg that fails (a full disk)
/// is: std::runtime_error with its exit status and last logged line, since
/// its videos are not whole.
/// With `contact_patch`, the top view also shows the local model's contact
/// patch (TopView::show_contact_patch).
RenderReport render_crossing(const RenderSettings& settings, const RailJointMesh& rails, const TriangleMesh& wheel,
                             const Trajectory& trajectory, const std::filesystem::path& out_dir,
                             const std::optional<PressureInputs>& contact_patch = std::nullopt);

/// "frame_00042.png"
std::string frame_file_name(long long k);

}  // namespace railjoint
